#ifndef EDYN_COLLISION_PAIR_MAP_HPP
#define EDYN_COLLISION_PAIR_MAP_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

namespace edyn {

/// Map from a 64-bit pair key to a 32-bit index, in one flat array (open addressing, linear
/// probing).
///
/// Unlike a node-based hash map it allocates only when it grows past its capacity, so
/// that pairs found and lost every step in a world that no longer grows cost no allocation.
/// Erasing shifts the following entries of the probe run back, so no tombstones pile up. Used
/// by the broadphase; not thread-safe.
class pair_map {
public:
    /// The value stored for `key`, or null when absent.
    /// @param key The key to look up.
    /// @return Pointer to the stored value, valid until the next insertion or erasure; null when
    ///         `key` is absent.
    [[nodiscard]] std::uint32_t *find(std::uint64_t key) noexcept {
        if (slots.empty()) return nullptr;
        for (auto i = home(key);; i = next(i)) {
            auto &slot = slots[i];
            if (!slot.used) return nullptr;
            if (slot.key == key) return &slot.value;
        }
    }
    /// The value stored for `key`, or null when absent (read-only).
    /// @param key The key to look up.
    /// @return Pointer to the stored value, or null.
    [[nodiscard]] const std::uint32_t *find(std::uint64_t key) const noexcept {
        return const_cast<pair_map *>(this)->find(key);
    }
    /// Whether `key` is present.
    /// @param key The key to look up.
    [[nodiscard]] bool contains(std::uint64_t key) const noexcept { return find(key) != nullptr; }

    /// Sets the value of `key`, adding it if absent; may allocate when the table grows.
    /// @param key The key.
    /// @param value The value to store for it.
    void insert_or_assign(std::uint64_t key, std::uint32_t value) {
        if (auto *existing = find(key)) {
            *existing = value;
            return;
        }
        // At most half full, so that probe runs stay short.
        if (2 * (count + 1) > slots.size()) grow();
        auto i = home(key);
        while (slots[i].used)
            i = next(i);
        slots[i] = {key, value, true};
        ++count;
    }

    /// Removes `key`.
    /// @param key The key to remove.
    /// @return Whether it was there.
    bool erase(std::uint64_t key) noexcept {
        if (slots.empty()) return false;
        auto i = home(key);
        for (;; i = next(i)) {
            if (!slots[i].used) return false;
            if (slots[i].key == key) break;
        }
        // Moves back every later entry of the run that may sit in the hole (its home is not
        // between the hole and it, cyclically), so that finds never stop early.
        auto hole = i;
        for (auto j = next(hole); slots[j].used; j = next(j)) {
            auto h = home(slots[j].key);
            bool movable = hole <= j ? (h <= hole || h > j) : (h <= hole && h > j);
            if (movable) {
                slots[hole] = slots[j];
                hole = j;
            }
        }
        slots[hole].used = false;
        --count;
        return true;
    }

    /// Removes every entry, keeping the allocated capacity.
    void clear() noexcept {
        for (auto &slot : slots)
            slot.used = false;
        count = 0;
    }

    /// Number of entries.
    [[nodiscard]] std::size_t size() const noexcept { return count; }

private:
    struct slot {
        std::uint64_t key{0};
        std::uint32_t value{0};
        bool used{false};
    };

    std::size_t home(std::uint64_t key) const noexcept {
        // Fibonacci hashing: the key's bits mixed into the top ones, which index the table.
        return std::size_t((key * 0x9e3779b97f4a7c15ull) >> shift);
    }
    std::size_t next(std::size_t i) const noexcept { return (i + 1) & (slots.size() - 1); }

    void grow() {
        auto old = std::move(slots);
        auto capacity = old.empty() ? std::size_t(16) : old.size() * 2;
        slots.assign(capacity, slot{});
        shift = 64;
        for (auto c = capacity; c > 1; c >>= 1)
            --shift;
        count = 0;
        for (auto &s : old) {
            if (s.used) insert_or_assign(s.key, s.value);
        }
    }

    std::vector<slot> slots;
    std::size_t count{0};
    unsigned shift{64};
};

} // namespace edyn

#endif // EDYN_COLLISION_PAIR_MAP_HPP
