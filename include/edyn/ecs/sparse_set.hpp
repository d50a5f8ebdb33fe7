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

// A set of entities with O(1) insertion, removal and membership test, kept in one contiguous
// ("packed") array. A paged sparse array maps an entity's index to its position in the packed
// array; pages of the sparse array are allocated on first use, so a set that only holds
// entities with high indices does not pay for the low ones.
//
// Removal moves the last entity of the packed array into the hole, so positions change on
// removal and the packed order is not the insertion order once anything has been removed.
// Iteration (`begin`/`end`) walks the packed array from the back, newest first: removing the
// entity being visited only disturbs entities already visited, which makes "remove the current
// one" safe in a loop. Inserting during iteration is safe too (the new entity lands behind the
// iterator and is not visited); removing any other entity is not.
//
// The base class holds no payload; `storage<T>` adds the components. Entities enter a set only
// through `storage<T>::emplace`.
class sparse_set {
    using value_type = entity_traits::value_type;
    static constexpr std::size_t sparse_page_size = 4096;
    static constexpr value_type null_slot = ~value_type{};

public:
    using size_type = std::size_t;
    static constexpr size_type npos = ~size_type{};

    // Random-access iterator over the entities, from the back of the packed array to its front.
    // It keeps a pointer to the packed vector and an offset, not a pointer into the vector, so
    // it survives the vector reallocating when entities are added.
    class iterator {
    public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = entity;
        using difference_type = std::ptrdiff_t;
        using pointer = const entity *;
        using reference = const entity &;

        iterator() = default;
        iterator(const std::vector<entity> *packed, difference_type offset) noexcept
            : packed(packed)
            , offset(offset) {}

        reference operator*() const noexcept { return (*packed)[static_cast<size_type>(offset - 1)]; }
        pointer operator->() const noexcept { return &**this; }
        reference operator[](difference_type n) const noexcept { return *(*this + n); }

        iterator &operator++() noexcept {
            --offset;
            return *this;
        }
        iterator operator++(int) noexcept {
            auto copy = *this;
            --offset;
            return copy;
        }
        iterator &operator--() noexcept {
            ++offset;
            return *this;
        }
        iterator operator--(int) noexcept {
            auto copy = *this;
            ++offset;
            return copy;
        }
        iterator &operator+=(difference_type n) noexcept {
            offset -= n;
            return *this;
        }
        iterator &operator-=(difference_type n) noexcept {
            offset += n;
            return *this;
        }
        friend iterator operator+(iterator it, difference_type n) noexcept { return it += n; }
        friend iterator operator+(difference_type n, iterator it) noexcept { return it += n; }
        friend iterator operator-(iterator it, difference_type n) noexcept { return it -= n; }
        friend difference_type operator-(const iterator &a, const iterator &b) noexcept {
            return b.offset - a.offset;
        }
        friend bool operator==(const iterator &a, const iterator &b) noexcept { return a.offset == b.offset; }
        friend auto operator<=>(const iterator &a, const iterator &b) noexcept {
            return b.offset <=> a.offset;
        }

        // Position in the packed array of the entity this iterator points to.
        [[nodiscard]] size_type index() const noexcept { return static_cast<size_type>(offset - 1); }

    private:
        const std::vector<entity> *packed{nullptr};
        difference_type offset{0};
    };

    sparse_set() = default;
    sparse_set(const sparse_set &) = delete;
    sparse_set &operator=(const sparse_set &) = delete;
    virtual ~sparse_set() = default;

    [[nodiscard]] size_type size() const noexcept { return packed.size(); }
    [[nodiscard]] bool empty() const noexcept { return packed.empty(); }
    [[nodiscard]] size_type capacity() const noexcept { return packed.capacity(); }

    // The packed array, oldest surviving insertion first (iteration goes the other way).
    [[nodiscard]] const entity *data() const noexcept { return packed.data(); }

    // True when `e` is in the set with this exact version: a stale handle whose index has
    // been reused by another entity is not contained.
    [[nodiscard]] bool contains(entity e) const noexcept {
        const auto slot = sparse_slot(to_index(e));
        return slot != null_slot && ((slot ^ to_integral(e)) >> entity_traits::index_bits) == 0;
    }

    // Position of `e` in the packed array (`data()[index(e)] == e`).
    [[nodiscard]] size_type index(entity e) const noexcept {
        EDYN_ASSERT(contains(e), "sparse_set::index: entity not in the set");
        return sparse_slot(to_index(e)) & entity_traits::index_mask;
    }

    // Position of `e` in the packed array, or `npos` when `e` is not in the set: one look-up
    // where `contains` followed by `index` would make two.
    [[nodiscard]] size_type find_index(entity e) const noexcept {
        const auto slot = sparse_slot(to_index(e));
        if (slot == null_slot || ((slot ^ to_integral(e)) >> entity_traits::index_bits) != 0) {
            return npos;
        }
        return slot & entity_traits::index_mask;
    }

    // Entity at a position of the packed array, or null past the end.
    [[nodiscard]] entity at(size_type pos) const noexcept { return pos < packed.size() ? packed[pos] : null; }

    [[nodiscard]] iterator begin() const noexcept {
        return {&packed, static_cast<std::ptrdiff_t>(packed.size())};
    }
    [[nodiscard]] iterator end() const noexcept { return {&packed, 0}; }

    // Removes `e` if present (and its component, in `storage<T>`); returns whether it was there.
    virtual bool remove(entity e) {
        if (!contains(e)) {
            return false;
        }
        swap_and_pop(e);
        return true;
    }

    virtual void clear() {
        for (auto e : packed) {
            sparse_ref(to_index(e)) = null_slot;
        }
        packed.clear();
    }

    virtual void reserve(size_type n) { packed.reserve(n); }

protected:
    // First half of an insertion: makes room for `e` at the back of the packed array. May throw
    // (allocation); on throw nothing changed. Until `commit_back` runs, `contains(e)` is false.
    void push_back_uncommitted(entity e) {
        EDYN_ASSERT(!contains(e), "sparse_set: entity already in the set");
        EDYN_ASSERT(to_index(e) != entity_traits::index_mask, "sparse_set: null entity");
        assure_page(to_index(e) / sparse_page_size);
        packed.push_back(e);
    }

    void commit_back() noexcept {
        const auto pos = static_cast<value_type>(packed.size() - 1);
        const auto e = packed.back();
        sparse_ref(to_index(e)) = (to_integral(e) & ~entity_traits::index_mask) | pos;
    }

    void abandon_back() noexcept { packed.pop_back(); }

    // Removes `e`, moving the last entity into its position.
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
