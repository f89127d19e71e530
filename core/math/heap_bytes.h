#pragma once
// Heap bytes held by the engine's arrays (capacity, not size: what the allocator gave them),
// split by what they grow with, so a memory estimate can scale each part on its own:
// per particle slot, per neighbour-list entry (pair), or neither (grid cells, scratch rows).
#include <cstddef>
#include <vector>

namespace demcal::core {

struct HeapBytes {
  size_t per_particle = 0;  // arrays with one element (or a few) per particle slot
  size_t per_pair = 0;      // arrays with one element per neighbour-list entry
  size_t other = 0;         // grid cells, per-chunk scratch, per-wall arrays

  size_t Total() const { return per_particle + per_pair + other; }
  HeapBytes& operator+=(const HeapBytes& b) {
    per_particle += b.per_particle, per_pair += b.per_pair, other += b.other;
    return *this;
  }
};

// Capacity in bytes of the given vectors together.
template <class... T>
size_t VectorBytes(const std::vector<T>&... v) {
  return (size_t{0} + ... + (v.capacity() * sizeof(T)));
}

}  // namespace demcal::core
