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
constexpr bool is_plane_pair = std::is_same_v<A, plane_shape> &&std::is_same_v<B, plane_shape>;

template<typename A, typename... Bs>
constexpr std::size_t count_row() {
    return (std::size_t{has_exact_overload<A, Bs>} + ...);
}

template<typename... Ts>
constexpr std::size_t count_overloads(std::type_identity<std::variant<Ts...>>) {
    return (count_row<Ts, Ts...>() + ...);
}

// Every ordered pair of shapes has its own overload, except plane against plane, which the
// dispatcher answers itself (nothing: both are static).
static_assert(count_overloads(std::type_identity<shapes_variant_t>{}) == num_shapes * num_shapes - 1,
              "collide() lacks an overload for some ordered pair of shapes_variant_t alternatives");
static_assert(!has_exact_overload<plane_shape, plane_shape>,
              "plane against plane is answered by the variant overload alone");

} // namespace

void collide(const shapes_variant_t &a, const shapes_variant_t &b, const collision_context &ctx,
             collision_result &result) {
    std::visit(
        [&](const auto &shape_a, const auto &shape_b) {
            using A = std::decay_t<decltype(shape_a)>;
            using B = std::decay_t<decltype(shape_b)>;
            if constexpr (!is_plane_pair<A, B>) {
                static_assert(has_exact_overload<A, B>,
                              "collide() lacks an overload for this pair of shapes");
                static_cast<collide_fn<A, B>> (&collide)(shape_a, shape_b, ctx, result);
            }
        },
        a, b);
}

} // namespace edyn
