#pragma once
// Rng: the engine's random source. A thin wrapper over std::mt19937_64 with its own uniform
// mapping so a seed gives the same numbers with every standard library.
#include <cstdint>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace demcal::core {

class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1) with 53 random bits.
  double Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  uint64_t Next() { return engine_(); }

  // Checkpointing: the engine state as text (the standard's portable representation).
  template <class A>
  void Serialize(A& a) {
    std::string state;
    if (a.writing()) {
      std::ostringstream os;
      os << engine_;
      state = os.str();
    }
    a.String(state);
    if (!a.writing() && a.ok()) {
      std::istringstream is(state);
      std::mt19937_64 engine;
      is >> engine;
      if (is.fail() || !(is >> std::ws).eof())
        throw std::runtime_error("a factory's random stream state is not readable");
      engine_ = engine;
    }
  }

 private:
  std::mt19937_64 engine_;
};

// Derives independent stream seeds from a run seed (splitmix64 finaliser).
inline uint64_t DeriveSeed(uint64_t seed, uint64_t stream) {
  uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace demcal::core
