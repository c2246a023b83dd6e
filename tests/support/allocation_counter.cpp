#include "allocation_counter.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

// Eigen (and C code) allocate with malloc, not operator new: with glibc, this program's own
// malloc, calloc and realloc come first for every object linked into it (the static hyst
// libraries included), count, and pass on to glibc's, whose blocks free() takes back as usual.
// AddressSanitizer brings its own allocator; under it only operator new is counted.
#if defined(__SANITIZE_ADDRESS__)
#define HYST_COUNTS_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HYST_COUNTS_MALLOC 0
#endif
#endif
#if !defined(HYST_COUNTS_MALLOC)
#if defined(__GLIBC__)
#define HYST_COUNTS_MALLOC 1
#else
#define HYST_COUNTS_MALLOC 0
#endif
#endif

namespace {
std::atomic<long> allocations{0};
}

#if HYST_COUNTS_MALLOC
extern "C" {
void* __libc_malloc(std::size_t size) noexcept;
void* __libc_calloc(std::size_t count, std::size_t size) noexcept;
void* __libc_realloc(void* pointer, std::size_t size) noexcept;

void* malloc(std::size_t size) noexcept {
  ++allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  ++allocations;
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) noexcept {
  ++allocations;
  return __libc_realloc(pointer, size);
}
}
namespace {
// operator new takes its memory uncounted: one allocation counts once.
void* raw_malloc(std::size_t size) {
  return __libc_malloc(size);
}
}  // namespace
#else
namespace {
void* raw_malloc(std::size_t size) {
  return std::malloc(size);
}
}  // namespace
#endif

// The replacements pair operator new with malloc and operator delete with free, which is correct;
// GCC cannot see that once they are inlined into callers and warns.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = raw_malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
// The nothrow forms too (std::stable_sort's buffer, for one): a nothrow new left to the runtime
// would be paired with the free() of the operator delete below.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  ++allocations;
  return raw_malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}

namespace hyst::test {

long allocation_count() {
  return allocations.load();
}

bool counts_malloc() {
  return HYST_COUNTS_MALLOC;
}

}  // namespace hyst::test
