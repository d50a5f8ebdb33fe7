#ifndef EDYN_ECS_STORAGE_HPP
#define EDYN_ECS_STORAGE_HPP

#include "edyn/config/assert.hpp"
#include "edyn/ecs/construct.hpp"
#include "edyn/ecs/entity.hpp"
#include "edyn/ecs/sparse_set.hpp"
#include <algorithm>
#include <bit>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace edyn {

/// The pool of one component type: a sparse set of entities plus, for each entity, its
/// component, at the same position as the entity in the packed array.
///
/// Empty types (tags, `std::is_empty_v`) store no component at all; `get` on them returns a
/// reference to one shared instance, so that generic code can treat every component alike.
///
/// Components live in fixed-size pages that are never moved, which gives these rules:
/// - Adding a component (`emplace`) never moves existing components: references and pointers to
///   components stay valid across insertions into the same pool or any other pool.
/// - Removing a component destroys it and moves the last component of the pool into its place:
///   a removal invalidates references to the removed component and to the pool's last component
///   (which now lives elsewhere), and changes positions in the packed array.
/// - `clear()` invalidates every reference into the pool.
/// - Iterators (`begin`/`end`, views) hold positions, not addresses; see `sparse_set`.
///
/// Functions called directly on a storage fire no signals; the registry's functions do. Obtain a
/// pool with `registry::storage<T>()`.
/// @tparam Type The component type: movable, neither a reference nor cv-qualified.
template<typename Type>
class storage final : public sparse_set {
    static_assert(std::is_same_v<Type, std::remove_cvref_t<Type>>,
                  "storage: component types must not be references or cv-qualified");
    static_assert(std::is_move_constructible_v<Type>, "storage: components must be movable");

    static constexpr bool has_payload = !std::is_empty_v<Type>;

public:
    /// The component type.
    using value_type = Type;
    /// Number of components per page. A power of two, so that finding a component's page is a
    /// shift; pages are about 16 KiB (one component per page when it is larger).
    static constexpr size_type page_capacity = std::bit_floor(std::max<size_type>(1, 16384 / sizeof(Type)));

    storage() = default;
    /// Destroys every component and frees the pages.
    ~storage() override { release_all(); }

    /// Adds `e` with a component built from `args` (parentheses, or braces for aggregates).
    /// Strong guarantee: if the component's constructor or an allocation throws, the pool is
    /// unchanged. Fires no signal (`registry::emplace` does, and checks its arguments).
    /// @param e An entity not in the pool and not null (preconditions, checked by `EDYN_ASSERT`).
    /// @param args Constructor arguments of the component; ignored for empty types.
    /// @return The new component (the shared instance for empty types).
    template<typename... Args>
    Type &emplace(entity e, Args &&...args) {
        if constexpr (has_payload) {
            const auto pos = size();
            assure_payload_page(pos / page_capacity);
            push_back_uncommitted(e);
            try {
                detail::construct_component(slot(pos), std::forward<Args>(args)...);
            } catch (...) {
                abandon_back();
                throw;
            }
            commit_back();
            return *slot(pos);
        } else {
            ((void)args, ...);
            push_back_uncommitted(e);
            commit_back();
            return placeholder();
        }
    }

    /// The component of `e`.
    /// @param e An entity of the pool (precondition, checked by `EDYN_ASSERT`).
    /// @return A reference, valid until this component or the pool's last one is removed.
    [[nodiscard]] Type &get(entity e) noexcept {
        EDYN_ASSERT(contains(e), "storage::get: entity does not have the component");
        return value_at(index(e));
    }

    /// Read-only `get`.
    /// @param e An entity of the pool (precondition, checked by `EDYN_ASSERT`).
    /// @return A reference to its component.
    [[nodiscard]] const Type &get(entity e) const noexcept {
        EDYN_ASSERT(contains(e), "storage::get: entity does not have the component");
        return value_at(index(e));
    }

    /// The component of `e`, if it has one.
    /// @param e Any entity, stale and null ones included.
    /// @return A pointer to the component, or null.
    [[nodiscard]] Type *try_get(entity e) noexcept { return contains(e) ? &value_at(index(e)) : nullptr; }

    /// Read-only `try_get`.
    /// @param e Any entity.
    /// @return A pointer to the component, or null.
    [[nodiscard]] const Type *try_get(entity e) const noexcept {
        return contains(e) ? &value_at(index(e)) : nullptr;
    }

    /// The component at a position of the packed array (the component of `data()[pos]`),
    /// without a look-up in the sparse array.
    /// @param pos Position, below `size()` (precondition, checked by `EDYN_ASSERT`).
    /// @return A reference to the component.
    [[nodiscard]] Type &value_at(size_type pos) noexcept {
        if constexpr (has_payload) {
            EDYN_ASSERT(pos < size(), "storage::value_at: position out of range");
            return *slot(pos);
        } else {
            return placeholder();
        }
    }

    /// Read-only `value_at`.
    /// @param pos Position, below `size()`.
    /// @return A reference to the component.
    [[nodiscard]] const Type &value_at(size_type pos) const noexcept {
        return const_cast<storage *>(this)->value_at(pos);
    }

    /// Removes `e` and its component if present; fires no signal.
    /// @param e Any entity.
    /// @return Whether it was there.
    bool remove(entity e) override {
        if (!contains(e)) {
            return false;
        }
        erase(e);
        return true;
    }

    /// Removes `e` and its component; the pool's last component moves into its place. Fires no
    /// signal.
    /// @param e An entity of the pool (precondition, checked by `EDYN_ASSERT`).
    void erase(entity e) {
        EDYN_ASSERT(contains(e), "storage::erase: entity does not have the component");
        if constexpr (has_payload) {
            const auto pos = index(e);
            const auto last = size() - 1;
            Type *back = slot(last);
            if (pos != last) {
                Type *hole = slot(pos);
                if constexpr (std::is_move_assignable_v<Type>) {
                    *hole = std::move(*back);
                } else {
                    std::destroy_at(hole);
                    ::new (static_cast<void *>(hole)) Type(std::move(*back));
                }
            }
            std::destroy_at(back);
        }
        swap_and_pop(e);
    }

    /// Destroys every component and removes every entity; fires no signal. Keeps the pages.
    void clear() override {
        destroy_payload();
        sparse_set::clear();
    }

    /// Allocates the packed array and the component pages for `n` entities.
    /// @param n Number of entities.
    void reserve(size_type n) override {
        sparse_set::reserve(n);
        if constexpr (has_payload) {
            if (n > 0) {
                for (size_type page = 0; page <= (n - 1) / page_capacity; ++page) {
                    assure_payload_page(page);
                }
            }
        }
    }

private:
    static Type &placeholder() noexcept {
        static Type instance{};
        return instance;
    }

    Type *slot(size_type pos) const noexcept { return pages[pos / page_capacity] + pos % page_capacity; }

    // A pool that outgrows its pages takes a sixteenth more than it needs (one page at least),
    // so that a count wavering about its highest (the contact manifolds of a settled heap, as
    // neighbours part and meet) does not allocate at every new high.
    void assure_payload_page(size_type page) {
        if (page < pages.size()) return;
        auto wanted = page + 2 + (page + 1) / 16;
        pages.reserve(wanted);
        while (pages.size() < wanted) {
            pages.push_back(std::allocator<Type>{}.allocate(page_capacity));
        }
    }

    void destroy_payload() noexcept {
        if constexpr (has_payload && !std::is_trivially_destructible_v<Type>) {
            for (size_type pos = 0; pos < size(); ++pos) {
                std::destroy_at(slot(pos));
            }
        }
    }

    void release_all() noexcept {
        destroy_payload();
        for (auto *page : pages) {
            std::allocator<Type>{}.deallocate(page, page_capacity);
        }
        pages.clear();
    }

    std::vector<Type *> pages;
};

} // namespace edyn

#endif // EDYN_ECS_STORAGE_HPP
