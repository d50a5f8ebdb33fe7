#ifndef EDYN_ECS_VIEW_HPP
#define EDYN_ECS_VIEW_HPP

#include "edyn/config/assert.hpp"
#include "edyn/ecs/entity.hpp"
#include "edyn/ecs/sparse_set.hpp"
#include "edyn/ecs/storage.hpp"
#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <tuple>
#include <type_traits>
#include <utility>

namespace edyn {

/// Component types a view leaves out: `registry.view<A, B>(edyn::exclude<C>)`.
/// @tparam Type The component types whose owners the view skips.
template<typename... Type>
struct exclude_t {
    /// Explicit, so that `{}` alone never converts to an exclusion list.
    explicit constexpr exclude_t() = default;
};

/// The value of `exclude_t<Type...>`, passed to `registry::view`: `edyn::exclude<C, D>`.
/// @tparam Type The component types whose owners the view skips.
template<typename... Type>
inline constexpr exclude_t<Type...> exclude{};

/// Component types a view iterates (EnTT's name; only used to spell view types).
/// @tparam Type The component types every entity of the view has.
template<typename... Type>
struct get_t {
    /// Explicit, so that `{}` alone never converts to a list of types.
    explicit constexpr get_t() = default;
};

namespace detail {

template<typename Type>
using storage_for_t =
    std::conditional_t<std::is_const_v<Type>, const storage<std::remove_const_t<Type>>, storage<Type>>;

template<typename Type>
inline constexpr bool is_tag_v = std::is_empty_v<std::remove_const_t<Type>>;

// `std::tuple<Type &>`, or `std::tuple<>` for empty types, which views do not hand out.
template<typename Type>
using ref_tuple_t = std::conditional_t<is_tag_v<Type>, std::tuple<>, std::tuple<Type &>>;

template<typename Func, typename Tuple>
struct is_applicable : std::false_type {};

template<typename Func, typename... Args>
struct is_applicable<Func, std::tuple<Args...>> : std::is_invocable<Func, Args...> {};

} // namespace detail

/// A view over the entities of a registry that have some components and lack others; only
/// `basic_view<get_t<Get...>, exclude_t<Exclude...>>` is defined.
template<typename, typename>
class basic_view;

/// A view over the entities that have every component in `Get` and none in `Exclude`, made by
/// `registry::view`.
///
/// It keeps pointers to the registry's pools, so it is cheap to copy, sees later changes to the
/// registry and must not outlive it. `const` component types give read-only access (views of a
/// `const registry` are always read-only).
///
/// Iteration walks the packed array of the smallest of the `Get` pools at the time the view was
/// made (the "leading" pool), from its back to its front (newest first), and checks every other
/// pool for each candidate. While iterating (`each`, range-for, `each()` ranges):
/// - removing components from, or destroying, the entity being visited is safe;
/// - adding components to any entity, and creating entities, is safe; an entity that becomes
///   part of the view during iteration may or may not be visited;
/// - removing components from, or destroying, entities other than the one being visited is not
///   safe: an entity may then be skipped or visited twice.
///
/// The callback of `each` receives `(entity, Get &...)` or `(Get &...)`, empty types left out.
/// @tparam Get The component types every entity of the view has (at least one).
/// @tparam Exclude The component types no entity of the view has.
template<typename... Get, typename... Exclude>
class basic_view<get_t<Get...>, exclude_t<Exclude...>> {
    static_assert(sizeof...(Get) > 0, "view: at least one component type");

    using pools_type = std::tuple<detail::storage_for_t<Get> *...>;
    using filter_type = std::array<const sparse_set *, sizeof...(Exclude)>;
    using components_type = decltype(std::tuple_cat(std::declval<detail::ref_tuple_t<Get>>()...));
    using entity_components_type =
        decltype(std::tuple_cat(std::tuple<entity>{}, std::declval<components_type>()));

    template<typename Type>
    static constexpr std::size_t index_of() noexcept {
        constexpr bool matches[] = {std::is_same_v<std::remove_const_t<Type>, std::remove_const_t<Get>>...};
        for (std::size_t i = 0; i < sizeof...(Get); ++i) {
            if (matches[i]) {
                return i;
            }
        }
        return sizeof...(Get);
    }

    template<std::size_t I>
    using get_type = std::tuple_element_t<I, std::tuple<Get...>>;

public:
    /// Unsigned integer type for counts of entities.
    using size_type = std::size_t;

    class each_iterator;

    /// Forward iterator over the entities of the view, in iteration order.
    class iterator {
        friend class each_iterator;

    public:
        /// Iterator category: forward.
        using iterator_category = std::forward_iterator_tag;
        /// Type of the elements: entities.
        using value_type = entity;
        /// Signed distance between two iterators.
        using difference_type = std::ptrdiff_t;
        /// Pointer to an element.
        using pointer = const entity *;
        /// Elements are returned by value.
        using reference = entity;

        /// A singular iterator, only good for assignment.
        iterator() = default;
        /// An iterator over `owner` placed at `offset` entities from the front of the leading
        /// pool, moved forward to the first entity of the view from there.
        /// @param owner The view; the iterator keeps a copy of it.
        /// @param offset Number of candidates left (the leading pool's size for `begin`, 0 for
        /// `end`).
        iterator(const basic_view &owner, size_type offset) noexcept
            : owner(owner)
            , offset(offset) {
            skip();
        }

        /// The entity pointed to.
        /// @return The entity.
        entity operator*() const noexcept { return owner.lead->data()[offset - 1]; }
        /// Steps to the next entity of the view.
        /// @return This iterator.
        iterator &operator++() noexcept {
            --offset;
            skip();
            return *this;
        }
        /// Steps to the next entity of the view.
        /// @return A copy of the iterator before the step.
        iterator operator++(int) noexcept {
            auto copy = *this;
            ++*this;
            return copy;
        }
        /// Whether two iterators of the same view point to the same position.
        /// @return True at the same position.
        friend bool operator==(const iterator &a, const iterator &b) noexcept { return a.offset == b.offset; }

    private:
        void skip() noexcept {
            // The clamp keeps the iterator in range when the visited entity was removed.
            offset = std::min(offset, owner.lead->size());
            while (offset > 0 && !owner.accept(owner.lead->data()[offset - 1])) {
                --offset;
            }
        }

        // A copy of the view (a few pointers): the iterator stays usable after a temporary view
        // it came from is gone.
        basic_view owner{};
        size_type offset{0};
    };

    /// Iterator over `std::tuple<entity, Get &...>` (empty types left out), for
    /// `for (auto [e, a, b] : view.each())`.
    class each_iterator {
    public:
        /// Iterator category: forward.
        using iterator_category = std::forward_iterator_tag;
        /// Type of the elements: a tuple of the entity and references to its components.
        using value_type = entity_components_type;
        /// Signed distance between two iterators.
        using difference_type = std::ptrdiff_t;
        /// Elements are built on the fly: there is no pointer to them.
        using pointer = void;
        /// Elements are returned by value (a tuple holding references).
        using reference = value_type;

        /// A singular iterator, only good for assignment.
        each_iterator() = default;
        /// An iterator that yields the components of the entities `it` walks.
        /// @param it The entity iterator to wrap.
        explicit each_iterator(iterator it) noexcept
            : it(it) {}

        /// The entity pointed to and its components.
        /// @return `std::tuple<entity, Get &...>`, empty types left out.
        value_type operator*() const { return it.owner.each_tuple(*it); }
        /// Steps to the next entity of the view.
        /// @return This iterator.
        each_iterator &operator++() noexcept {
            ++it;
            return *this;
        }
        /// Steps to the next entity of the view.
        /// @return A copy of the iterator before the step.
        each_iterator operator++(int) noexcept {
            auto copy = *this;
            ++it;
            return copy;
        }
        /// Whether two iterators of the same view point to the same position.
        /// @return True at the same position.
        friend bool operator==(const each_iterator &a, const each_iterator &b) noexcept {
            return a.it == b.it;
        }

    private:
        iterator it;
    };

    /// The range returned by `each()`, for range-for with structured bindings.
    struct each_range {
        each_iterator first; ///< First element.
        each_iterator last;  ///< Past the last element.
        /// Start of the range.
        /// @return `first`.
        [[nodiscard]] each_iterator begin() const noexcept { return first; }
        /// End of the range.
        /// @return `last`.
        [[nodiscard]] each_iterator end() const noexcept { return last; }
    };

    /// An unusable view, only good for assignment.
    basic_view() = default;

    /// A view over the given pools; `registry::view` makes them, applications need not. The
    /// smallest pool at this moment becomes the leading pool.
    /// @param pools The pool of each type of `Get`, in order.
    /// @param filter The pools of the `Exclude` types.
    basic_view(detail::storage_for_t<Get> &...pools, filter_type filter) noexcept
        : pools(&pools...)
        , filter(filter) {
        const sparse_set *candidates[] = {&pools...};
        for (size_type i = 0; i < sizeof...(Get); ++i) {
            if (lead == nullptr || candidates[i]->size() < lead->size()) {
                lead = candidates[i];
                lead_index = i;
            }
        }
    }

    /// The leading pool: its entities, from the back of its packed array to the front, are the
    /// candidates iteration checks (with `contains`), so a program may check them on several
    /// threads and keep the view's order.
    /// @return The leading pool, valid while the registry is.
    [[nodiscard]] const sparse_set &handle() const noexcept { return *lead; }

    /// Upper bound of the number of entities: the size of the leading pool.
    /// @return The size of the leading pool now.
    [[nodiscard]] size_type size_hint() const noexcept { return lead->size(); }

    /// Exact number of entities; only single-component views without exclusions know it cheaply,
    /// so it exists only for them.
    /// @return The size of the one pool.
    [[nodiscard]] size_type size() const noexcept requires(sizeof...(Get) == 1 && sizeof...(Exclude) == 0) {
        return lead->size();
    }

    /// Whether the view has no entity; walks the leading pool until it finds one.
    /// @return True when no entity matches.
    [[nodiscard]] bool empty() const noexcept { return begin() == end(); }

    /// Iterator to the first entity of the view.
    /// @return An iterator over entities (`for (auto e : view)`).
    [[nodiscard]] iterator begin() const noexcept { return iterator{*this, lead->size()}; }
    /// Iterator past the last entity of the view.
    /// @return The end iterator.
    [[nodiscard]] iterator end() const noexcept { return iterator{*this, 0}; }

    /// First entity in iteration order (the newest of the leading pool).
    /// @return The entity, or null when the view is empty.
    [[nodiscard]] entity front() const noexcept {
        const auto it = begin();
        return it != end() ? *it : entity(null);
    }

    /// Last entity in iteration order.
    /// @return The entity, or null when the view is empty.
    [[nodiscard]] entity back() const noexcept {
        for (size_type pos = 0; pos < lead->size(); ++pos) {
            if (accept(lead->data()[pos])) {
                return lead->data()[pos];
            }
        }
        return null;
    }

    /// Whether `e` has every `Get` component and no `Exclude` component.
    /// @param e Any entity, stale and null ones included.
    /// @return True when `e` belongs to the view.
    [[nodiscard]] bool contains(entity e) const noexcept {
        return std::apply([e](auto *...pool) { return (pool->contains(e) && ...); }, pools) && !excluded(e);
    }

    /// Components of an entity of the view: `get<T>(e)` gives `T &`; `get<T, U>(e)` a tuple of
    /// references; `get(e)` all of them.
    /// @tparam Type Some of the `Get` types, or none for all of them.
    /// @param e An entity of the view (precondition: `contains(e)`, checked by `EDYN_ASSERT`).
    /// @return A reference or a tuple of references.
    template<typename... Type>
    [[nodiscard]] decltype(auto) get(entity e) const noexcept {
        EDYN_ASSERT(contains(e), "view::get: entity is not in the view");
        if constexpr (sizeof...(Type) == 0) {
            return std::apply([e](auto *...pool) { return std::tuple<Get &...>{pool->get(e)...}; }, pools);
        } else if constexpr (sizeof...(Type) == 1) {
            return (std::get<index_of<Type>()>(pools)->get(e), ...);
        } else {
            return std::tuple<decltype(std::get<index_of<Type>()>(pools)->get(e))...>{
                std::get<index_of<Type>()>(pools)->get(e)...};
        }
    }

    /// The pool of one of the view's component types.
    /// @tparam Type One of the `Get` types (checked at compile time).
    /// @return A reference to the pool, const for const types.
    template<typename Type>
    [[nodiscard]] auto &storage() const noexcept {
        static_assert(index_of<Type>() < sizeof...(Get), "view::storage: not a component of this view");
        return *std::get<index_of<Type>()>(pools);
    }

    /// Calls `func(entity, components...)` or `func(components...)` for every entity of the
    /// view, in iteration order, empty component types left out of the arguments. Faster than
    /// range-for: each component is fetched once.
    /// @param func The callback, taking components by reference (`const` for read-only types).
    template<typename Func>
    void each(Func func) const {
        static_assert(detail::is_applicable<Func &, entity_components_type>::value ||
                          detail::is_applicable<Func &, components_type>::value,
                      "view::each: callback must take (entity, components...) or (components...), "
                      "empty component types left out");
        each_dispatch(func, std::index_sequence_for<Get...>{});
    }

    /// A range of `std::tuple<entity, Get &...>` (empty types left out), for
    /// `for (auto [e, a, b] : view.each())`.
    /// @return The range.
    [[nodiscard]] each_range each() const noexcept { return {each_iterator{begin()}, each_iterator{end()}}; }

private:
    [[nodiscard]] bool accept(entity e) const noexcept {
        if constexpr (sizeof...(Get) == 1 && sizeof...(Exclude) == 0) {
            return true;
        } else {
            return contains(e);
        }
    }

    [[nodiscard]] bool excluded(entity e) const noexcept {
        return std::any_of(filter.begin(), filter.end(),
                           [e](const sparse_set *set) { return set->contains(e); });
    }

    template<typename Func, std::size_t... I>
    void each_dispatch(Func &func, std::index_sequence<I...> seq) const {
        // Instantiates one loop per possible leading pool, so that the leading component is
        // fetched by position rather than looked up.
        (void)((lead_index == I ? (each_from<I>(func, seq), true) : false) || ...);
    }

    template<std::size_t Lead, typename Func, std::size_t... I>
    void each_from(Func &func, std::index_sequence<I...>) const {
        auto &pool = *std::get<Lead>(pools);
        for (size_type pos = pool.size(); pos > 0; pos = std::min(pos - 1, pool.size())) {
            const entity e = pool.data()[pos - 1];
            // Position of `e` in each pool, found once and used for both the test and the fetch.
            std::array<size_type, sizeof...(Get)> index;
            const bool in_all =
                ((I == Lead ? (index[I] = pos - 1, true)
                            : (index[I] = std::get<I>(pools)->find_index(e)) != sparse_set::npos) &&
                 ...);
            if (!in_all || excluded(e)) {
                continue;
            }
            auto components = std::tuple_cat(component_at<I>(index[I])...);
            invoke(func, e, components);
        }
    }

    template<std::size_t I>
    [[nodiscard]] auto component_at(size_type pos) const noexcept {
        using type = get_type<I>;
        if constexpr (detail::is_tag_v<type>) {
            return std::tuple<>{};
        } else {
            return std::tuple<type &>{std::get<I>(pools)->value_at(pos)};
        }
    }

    template<typename Func>
    static void invoke(Func &func, entity e, components_type &components) {
        if constexpr (detail::is_applicable<Func &, entity_components_type>::value) {
            std::apply([&func, e](auto &...component) { func(e, component...); }, components);
        } else {
            std::apply(func, components);
        }
    }

    [[nodiscard]] auto each_tuple(entity e) const {
        return std::tuple_cat(
            std::tuple<entity>{e},
            std::apply([e](auto *...pool) { return std::tuple_cat(component_of<Get>(*pool, e)...); }, pools));
    }

    template<typename Type, typename Pool>
    [[nodiscard]] static auto component_of(Pool &pool, entity e) noexcept {
        if constexpr (detail::is_tag_v<Type>) {
            return std::tuple<>{};
        } else {
            return std::tuple<Type &>{pool.get(e)};
        }
    }

    pools_type pools{};
    filter_type filter{};
    const sparse_set *lead{nullptr};
    size_type lead_index{0};
};

/// EnTT's spelling of a view type: `edyn::view<edyn::get_t<A, B>, edyn::exclude_t<C>>`.
/// @tparam Get `get_t` of the component types iterated.
/// @tparam Exclude `exclude_t` of the component types left out.
template<typename Get, typename Exclude = exclude_t<>>
using view = basic_view<Get, Exclude>;

} // namespace edyn

#endif // EDYN_ECS_VIEW_HPP
