// The program's global operator new: the standard one, except that a failure notes the size
// asked for, so that the last-resort "out of memory" line of run_cli() can name it. Linked into
// the hyst program only (the command-line library and the fuzz target keep the standard one).
// Under AddressSanitizer the sanitizer's allocator stays in place.

#include <cstddef>
#include <cstdlib>
#include <new>

#include "cli_app.hpp"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HYST_SANITIZER_ALLOCATOR 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define HYST_SANITIZER_ALLOCATOR 1
#endif

#ifndef HYST_SANITIZER_ALLOCATOR

namespace {

// The standard's loop: ask the new-handler for memory until there is none to free.
void* allocate(std::size_t size, std::size_t alignment) {
  if (size == 0) size = 1;
  while (true) {
    void* memory =
        alignment <= alignof(std::max_align_t)
            ? std::malloc(size)
            : std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
    if (memory != nullptr) return memory;
    if (std::new_handler handler = std::get_new_handler()) {
      handler();
      continue;
    }
    hyst::cli::note_failed_allocation(size);
    throw std::bad_alloc();
  }
}

}  // namespace

void* operator new(std::size_t size) {
  return allocate(size, alignof(std::max_align_t));
}
void* operator new[](std::size_t size) {
  return allocate(size, alignof(std::max_align_t));
}
void* operator new(std::size_t size, std::align_val_t alignment) {
  return allocate(size, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  return allocate(size, static_cast<std::size_t>(alignment));
}
void operator delete(void* memory) noexcept {
  std::free(memory);
}
void operator delete[](void* memory) noexcept {
  std::free(memory);
}
void operator delete(void* memory, std::size_t) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, std::size_t) noexcept {
  std::free(memory);
}
void operator delete(void* memory, std::align_val_t) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, std::align_val_t) noexcept {
  std::free(memory);
}
void operator delete(void* memory, std::size_t, std::align_val_t) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, std::size_t, std::align_val_t) noexcept {
  std::free(memory);
}

#endif
