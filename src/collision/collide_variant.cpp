#include "edyn/collision/collide.hpp"
#include <cstddef>
#include <type_traits>
#include <variant>

namespace edyn {

namespace {

template<typename A, typename B>
using collide_fn = void (*)(const A &, const B &, const collision_context &, collision_result &);

// Whether collide() has an overload taking exactly (A, B). A shape converts implicitly to
// shapes_variant_t, so a plain call with a missing overload would pick the variant overload below
// and recurse forever; taking the address with the exact signature rules that out.
template<typename A, typename B>
constexpr bool has_exact_overload = requires {
    static_cast<collide_fn<A, B>>(&collide);
};

template<typename A, typename B>
constexpr bool is_static_pair = is_static_only_shape_v<A> &&is_static_only_shape_v<B>;

template<typename A, typename... Bs>
constexpr std::size_t count_row() {
    return (std::size_t{has_exact_overload<A, Bs>} + ...);
}

template<typename... Ts>
constexpr std::size_t count_overloads(std::type_identity<std::variant<Ts...>>) {
    return (count_row<Ts, Ts...>() + ...);
}

template<typename... Ts>
constexpr std::size_t count_static_only(std::type_identity<std::variant<Ts...>>) {
    return (std::size_t{is_static_only_shape_v<Ts>} + ...);
}

constexpr auto num_static_only = count_static_only(std::type_identity<shapes_variant_t>{});

// Every ordered pair of shapes has its own overload, except pairs of static-only shapes, which
// the dispatcher answers itself (nothing: both are static).
static_assert(count_overloads(std::type_identity<shapes_variant_t>{}) ==
                  num_shapes * num_shapes - num_static_only * num_static_only,
              "collide() lacks an overload for some ordered pair of shapes_variant_t alternatives");
static_assert(!has_exact_overload<plane_shape, plane_shape> && !has_exact_overload<mesh_shape, mesh_shape> &&
                  !has_exact_overload<plane_shape, mesh_shape> &&
                  !has_exact_overload<mesh_shape, plane_shape>,
              "pairs of static-only shapes are answered by the variant overload alone");
static_assert(!has_exact_overload<paged_mesh_shape, paged_mesh_shape> &&
                  !has_exact_overload<paged_mesh_shape, mesh_shape> &&
                  !has_exact_overload<plane_shape, paged_mesh_shape>,
              "pairs of static-only shapes are answered by the variant overload alone");

} // namespace

void collide(const shapes_variant_t &a, const shapes_variant_t &b, const collision_context &ctx,
             collision_result &result) {
    std::visit(
        [&](const auto &shape_a, const auto &shape_b) {
            using A = std::decay_t<decltype(shape_a)>;
            using B = std::decay_t<decltype(shape_b)>;
            if constexpr (!is_static_pair<A, B>) {
                static_assert(has_exact_overload<A, B>,
                              "collide() lacks an overload for this pair of shapes");
                static_cast<collide_fn<A, B>> (&collide)(shape_a, shape_b, ctx, result);
            }
        },
        a, b);
}

} // namespace edyn
