#pragma once
// CPython's random module (Mersenne Twister MT19937, init_by_array seeding, 53-bit random()), so
// that tests can rebuild the exact random weights and inputs of the reference's Python checks
// (../shared/reference/checks/*.py call random.seed(n) with a small integer n).

#include <array>
#include <cstdint>

namespace hyst::test {

class PythonRandom {
 public:
  // random.seed(n) for 0 <= n < 2^32: init_by_array with the key {n}.
  explicit PythonRandom(std::uint32_t seed) {
    init_genrand(19650218U);
    std::size_t i = 1;
    for (std::size_t k = kN; k > 0; --k) {  // key length 1: j stays 0
      mt_[i] = (mt_[i] ^ ((mt_[i - 1] ^ (mt_[i - 1] >> 30)) * 1664525U)) + seed;
      if (++i >= kN) {
        mt_[0] = mt_[kN - 1];
        i = 1;
      }
    }
    for (std::size_t k = kN - 1; k > 0; --k) {
      mt_[i] = (mt_[i] ^ ((mt_[i - 1] ^ (mt_[i - 1] >> 30)) * 1566083941U)) -
               static_cast<std::uint32_t>(i);
      if (++i >= kN) {
        mt_[0] = mt_[kN - 1];
        i = 1;
      }
    }
    mt_[0] = 0x80000000U;
  }

  // random.random(): a double in [0, 1) from two 32-bit outputs.
  double random() {
    const std::uint32_t a = next() >> 5;
    const std::uint32_t b = next() >> 6;
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
  }
  // random.uniform(a, b) = a + (b - a) * random().
  double uniform(double a, double b) { return a + (b - a) * random(); }

 private:
  static constexpr std::size_t kN = 624;
  static constexpr std::size_t kM = 397;

  void init_genrand(std::uint32_t s) {
    mt_[0] = s;
    for (std::size_t i = 1; i < kN; ++i) {
      mt_[i] = 1812433253U * (mt_[i - 1] ^ (mt_[i - 1] >> 30)) + static_cast<std::uint32_t>(i);
    }
    index_ = kN;
  }

  std::uint32_t next() {
    if (index_ >= kN) {
      for (std::size_t k = 0; k < kN; ++k) {
        const std::uint32_t y = (mt_[k] & 0x80000000U) | (mt_[(k + 1) % kN] & 0x7fffffffU);
        mt_[k] = mt_[(k + kM) % kN] ^ (y >> 1) ^ ((y & 1U) != 0 ? 0x9908b0dfU : 0U);
      }
      index_ = 0;
    }
    std::uint32_t y = mt_[index_++];
    y ^= y >> 11;
    y ^= (y << 7) & 0x9d2c5680U;
    y ^= (y << 15) & 0xefc60000U;
    y ^= y >> 18;
    return y;
  }

  std::array<std::uint32_t, kN> mt_{};
  std::size_t index_ = kN;
};

}  // namespace hyst::test
