#ifndef EDYN_ECS_SPARSE_SET_HPP
#define EDYN_ECS_SPARSE_SET_HPP

#include "edyn/config/assert.hpp"
#include "edyn/ecs/entity.hpp"
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <memory>
#include <vector>

namespace edyn {

/// A set of entities with O(1) insertion, removal and membership test, kept in one contiguous
/// ("packed") array; the base of every component pool.
///
/// A paged sparse array maps an entity's index to its position in the packed array; pages of the
/// sparse array are allocated on first use, so a set that only holds entities with high indices
/// does not pay for the low ones.
///
/// Removal moves the last entity of the packed array into the hole, so positions change on
/// removal and the packed order is not the insertion order once anything has been removed.
/// Iteration (`begin`/`end`) walks the packed array from the back, newest first: removing the
/// entity being visited only disturbs entities already visited, which makes "remove the current
/// one" safe in a loop. Inserting during iteration is safe too (the new entity lands behind the
/// iterator and is not visited); removing any other entity is not.
///
/// The base class holds no payload; `storage<T>` adds the components. Entities enter a set only
/// through `storage<T>::emplace`.
class sparse_set {
    using value_type = entity_traits::value_type;
    static constexpr std::size_t sparse_page_size = 4096;
    static constexpr value_type null_slot = ~value_type{};

public:
    /// Unsigned integer type for counts and positions.
    using size_type = std::size_t;
    /// Position returned by `find_index` for an entity that is not in the set.
    static constexpr size_type npos = ~size_type{};

    /// Random-access iterator over the entities, from the back of the packed array to its front.
    ///
    /// It keeps a pointer to the packed vector and an offset, not a pointer into the vector, so
    /// it survives the vector reallocating when entities are added.
    class iterator {
    public:
        /// Iterator category: random access.
        using iterator_category = std::random_access_iterator_tag;
        /// Type of the elements: entities.
        using value_type = entity;
        /// Signed distance between two iterators.
        using difference_type = std::ptrdiff_t;
        /// Pointer to an element.
        using pointer = const entity *;
        /// Reference to an element.
        using reference = const entity &;

        /// A singular iterator, only good for assignment.
        iterator() = default;
        /// An iterator at `offset` entities from the front of `packed` (`offset - 1` is the
        /// position it points to; 0 is the end).
        /// @param packed The packed array of the set.
        /// @param offset Number of entities before the end of iteration.
        iterator(const std::vector<entity> *packed, difference_type offset) noexcept
            : packed(packed)
            , offset(offset) {}

        /// The entity pointed to.
        /// @return A reference into the packed array, valid until it changes.
        reference operator*() const noexcept { return (*packed)[static_cast<size_type>(offset - 1)]; }
        /// Pointer to the entity pointed to.
        /// @return The address of the element in the packed array.
        pointer operator->() const noexcept { return &**this; }
        /// The entity `n` steps further in iteration order.
        /// @param n Number of steps (towards the front of the packed array when positive).
        /// @return A reference into the packed array.
        reference operator[](difference_type n) const noexcept { return *(*this + n); }

        /// Steps to the next entity (towards the front of the packed array).
        /// @return This iterator.
        iterator &operator++() noexcept {
            --offset;
            return *this;
        }
        /// Steps to the next entity.
        /// @return A copy of the iterator before the step.
        iterator operator++(int) noexcept {
            auto copy = *this;
            --offset;
            return copy;
        }
        /// Steps back to the previous entity (towards the back of the packed array).
        /// @return This iterator.
        iterator &operator--() noexcept {
            ++offset;
            return *this;
        }
        /// Steps back to the previous entity.
        /// @return A copy of the iterator before the step.
        iterator operator--(int) noexcept {
            auto copy = *this;
            ++offset;
            return copy;
        }
        /// Moves `n` steps forward.
        /// @param n Number of steps; negative moves backward.
        /// @return This iterator.
        iterator &operator+=(difference_type n) noexcept {
            offset -= n;
            return *this;
        }
        /// Moves `n` steps backward.
        /// @param n Number of steps; negative moves forward.
        /// @return This iterator.
        iterator &operator-=(difference_type n) noexcept {
            offset += n;
            return *this;
        }
        /// The iterator `n` steps after `it`.
        /// @return The moved copy.
        friend iterator operator+(iterator it, difference_type n) noexcept { return it += n; }
        /// The iterator `n` steps after `it`.
        /// @return The moved copy.
        friend iterator operator+(difference_type n, iterator it) noexcept { return it += n; }
        /// The iterator `n` steps before `it`.
        /// @return The moved copy.
        friend iterator operator-(iterator it, difference_type n) noexcept { return it -= n; }
        /// Number of steps from `b` to `a`.
        /// @return The signed distance, positive when `a` comes after `b` in iteration order.
        friend difference_type operator-(const iterator &a, const iterator &b) noexcept {
            return b.offset - a.offset;
        }
        /// Whether two iterators of the same set point to the same position.
        /// @return True at the same position.
        friend bool operator==(const iterator &a, const iterator &b) noexcept { return a.offset == b.offset; }
        /// Orders two iterators of the same set by iteration order.
        /// @return The ordering of `a` relative to `b`.
        friend auto operator<=>(const iterator &a, const iterator &b) noexcept {
            return b.offset <=> a.offset;
        }

        /// Position in the packed array of the entity this iterator points to.
        /// @return An index into `data()`.
        [[nodiscard]] size_type index() const noexcept { return static_cast<size_type>(offset - 1); }

    private:
        const std::vector<entity> *packed{nullptr};
        difference_type offset{0};
    };

    sparse_set() = default;
    sparse_set(const sparse_set &) = delete;
    sparse_set &operator=(const sparse_set &) = delete;
    /// Destroys the set (and, in `storage<T>`, its components).
    virtual ~sparse_set() = default;

    /// Number of entities in the set.
    /// @return The length of the packed array.
    [[nodiscard]] size_type size() const noexcept { return packed.size(); }
    /// Whether the set holds no entity.
    /// @return True when `size() == 0`.
    [[nodiscard]] bool empty() const noexcept { return packed.empty(); }
    /// Number of entities the packed array holds without reallocating.
    /// @return The capacity of the packed array.
    [[nodiscard]] size_type capacity() const noexcept { return packed.capacity(); }

    /// The packed array, oldest surviving insertion first (iteration goes the other way).
    /// @return A pointer to `size()` entities, invalidated by insertions and removals.
    [[nodiscard]] const entity *data() const noexcept { return packed.data(); }

    /// True when `e` is in the set with this exact version: a stale handle whose index has
    /// been reused by another entity is not contained.
    /// @param e Any entity, null included.
    /// @return Whether `e` is in the set.
    [[nodiscard]] bool contains(entity e) const noexcept {
        const auto slot = sparse_slot(to_index(e));
        return slot != null_slot && ((slot ^ to_integral(e)) >> entity_traits::index_bits) == 0;
    }

    /// Position of `e` in the packed array (`data()[index(e)] == e`).
    /// @param e An entity of the set (precondition, checked by `EDYN_ASSERT`).
    /// @return Its position.
    [[nodiscard]] size_type index(entity e) const noexcept {
        EDYN_ASSERT(contains(e), "sparse_set::index: entity not in the set");
        return sparse_slot(to_index(e)) & entity_traits::index_mask;
    }

    /// Position of `e` in the packed array, or `npos` when `e` is not in the set: one look-up
    /// where `contains` followed by `index` would make two.
    /// @param e Any entity.
    /// @return Its position, or `npos`.
    [[nodiscard]] size_type find_index(entity e) const noexcept {
        const auto slot = sparse_slot(to_index(e));
        if (slot == null_slot || ((slot ^ to_integral(e)) >> entity_traits::index_bits) != 0) {
            return npos;
        }
        return slot & entity_traits::index_mask;
    }

    /// Entity at a position of the packed array.
    /// @param pos Position in the packed array.
    /// @return The entity there, or null past the end.
    [[nodiscard]] entity at(size_type pos) const noexcept { return pos < packed.size() ? packed[pos] : null; }

    /// Iterator to the first entity in iteration order: the back of the packed array.
    /// @return An iterator that stays valid while entities are added.
    [[nodiscard]] iterator begin() const noexcept {
        return {&packed, static_cast<std::ptrdiff_t>(packed.size())};
    }
    /// Iterator past the last entity in iteration order (the front of the packed array).
    /// @return The end iterator.
    [[nodiscard]] iterator end() const noexcept { return {&packed, 0}; }

    /// Removes `e` if present (and its component, in `storage<T>`). The last entity of the packed
    /// array moves into its position. No signal fires: use the registry's functions for that.
    /// @param e Any entity.
    /// @return Whether it was there.
    virtual bool remove(entity e) {
        if (!contains(e)) {
            return false;
        }
        swap_and_pop(e);
        return true;
    }

    /// Removes every entity (and, in `storage<T>`, every component); fires no signal.
    virtual void clear() {
        for (auto e : packed) {
            sparse_ref(to_index(e)) = null_slot;
        }
        packed.clear();
    }

    /// Allocates room for `n` entities (and, in `storage<T>`, their components), so that
    /// insertions up to that count do not allocate.
    /// @param n Number of entities.
    virtual void reserve(size_type n) { packed.reserve(n); }

protected:
    /// First half of an insertion: makes room for `e` at the back of the packed array. May throw
    /// (allocation); on throw nothing changed. Until `commit_back` runs, `contains(e)` is false.
    /// @param e An entity not in the set and not null (preconditions, checked by `EDYN_ASSERT`).
    void push_back_uncommitted(entity e) {
        EDYN_ASSERT(!contains(e), "sparse_set: entity already in the set");
        EDYN_ASSERT(to_index(e) != entity_traits::index_mask, "sparse_set: null entity");
        assure_page(to_index(e) / sparse_page_size);
        packed.push_back(e);
    }

    /// Second half of an insertion: makes the entity pushed by `push_back_uncommitted` a member.
    void commit_back() noexcept {
        const auto pos = static_cast<value_type>(packed.size() - 1);
        const auto e = packed.back();
        sparse_ref(to_index(e)) = (to_integral(e) & ~entity_traits::index_mask) | pos;
    }

    /// Undoes `push_back_uncommitted` when constructing the component failed.
    void abandon_back() noexcept { packed.pop_back(); }

    /// Removes `e`, moving the last entity into its position.
    /// @param e An entity of the set (precondition).
    void swap_and_pop(entity e) noexcept {
        const auto pos = index(e);
        const auto last = packed.back();
        packed[pos] = last;
        auto &last_slot = sparse_ref(to_index(last));
        last_slot = (last_slot & ~entity_traits::index_mask) | static_cast<value_type>(pos);
        sparse_ref(to_index(e)) = null_slot;
        packed.pop_back();
    }

private:
    [[nodiscard]] value_type sparse_slot(value_type idx) const noexcept {
        const auto page = idx / sparse_page_size;
        if (page >= sparse.size() || !sparse[page]) {
            return null_slot;
        }
        return sparse[page][idx % sparse_page_size];
    }

    value_type &sparse_ref(value_type idx) noexcept {
        return sparse[idx / sparse_page_size][idx % sparse_page_size];
    }

    void assure_page(std::size_t page) {
        if (page >= sparse.size()) {
            sparse.resize(page + 1);
        }
        if (!sparse[page]) {
            sparse[page] = std::make_unique<value_type[]>(sparse_page_size);
            std::fill_n(sparse[page].get(), sparse_page_size, null_slot);
        }
    }

    // Each slot holds the position in `packed` in its index bits and the entity's version in
    // its version bits, so that `contains` needs no access to `packed`.
    std::vector<std::unique_ptr<value_type[]>> sparse;
    std::vector<entity> packed;
};

} // namespace edyn

#endif // EDYN_ECS_SPARSE_SET_HPP
