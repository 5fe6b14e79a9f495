// One sparse set per component type: a sparse array from entity index to a dense slot, and
// dense arrays of owners and values, so lookup is O(1), iteration is over packed values, and
// removal swaps the last value into the hole (values move; do not keep pointers across it).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace lg {

template <class T>
class ComponentSet {
 public:
  static constexpr uint32_t absent = 0xffffffffu;

  bool contains(uint32_t entity) const { return entity < sparse_.size() && sparse_[entity] != absent; }
  size_t size() const { return values_.size(); }

  T* find(uint32_t entity) { return contains(entity) ? &values_[sparse_[entity]] : nullptr; }
  const T* find(uint32_t entity) const { return contains(entity) ? &values_[sparse_[entity]] : nullptr; }

  // Adds or replaces the entity's value.
  T& put(uint32_t entity, T value) {
    if (T* existing = find(entity)) return *existing = std::move(value);
    if (entity >= sparse_.size()) sparse_.resize(entity + 1, absent);
    sparse_[entity] = static_cast<uint32_t>(values_.size());
    owners_.push_back(entity);
    values_.push_back(std::move(value));
    return values_.back();
  }

  bool erase(uint32_t entity) {
    if (!contains(entity)) return false;
    uint32_t slot = sparse_[entity];
    uint32_t last = static_cast<uint32_t>(values_.size() - 1);
    if (slot != last) {
      values_[slot] = std::move(values_[last]);
      owners_[slot] = owners_[last];
      sparse_[owners_[slot]] = slot;
    }
    values_.pop_back();
    owners_.pop_back();
    sparse_[entity] = absent;
    return true;
  }

  // Entity indices in dense order (the order of iteration).
  const std::vector<uint32_t>& owners() const { return owners_; }

 private:
  std::vector<uint32_t> sparse_;
  std::vector<uint32_t> owners_;
  std::vector<T> values_;
};

}  // namespace lg
