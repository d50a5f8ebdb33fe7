#ifndef EDYN_SHAPES_SHAPES_HPP
#define EDYN_SHAPES_SHAPES_HPP

#include "edyn/shapes/box_shape.hpp"
#include "edyn/shapes/capsule_shape.hpp"
#include "edyn/shapes/compound_shape.hpp"
#include "edyn/shapes/cylinder_shape.hpp"
#include "edyn/shapes/mesh_shape.hpp"
#include "edyn/shapes/paged_mesh_shape.hpp"
#include "edyn/shapes/plane_shape.hpp"
#include "edyn/shapes/polyhedron_shape.hpp"
#include "edyn/shapes/sphere_shape.hpp"
#include <concepts>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <variant>

namespace edyn {

/// Every shape a rigid body can have, e.g. for `rigidbody_def::shape` or rigidbody_set_shape().
using shapes_variant_t = std::variant<plane_shape, sphere_shape, cylinder_shape, capsule_shape, box_shape,
                                      polyhedron_shape, compound_shape, mesh_shape, paged_mesh_shape>;

/// The same types as shapes_variant_t, in the same order, as a tuple, to iterate over at compile
/// time (e.g. one registry view per shape).
using shapes_tuple_t = std::tuple<plane_shape, sphere_shape, cylinder_shape, capsule_shape, box_shape,
                                  polyhedron_shape, compound_shape, mesh_shape, paged_mesh_shape>;

namespace detail {
template<typename T, typename Variant>
struct variant_index;

template<typename T, typename... Ts>
struct variant_index<T, std::variant<Ts...>> {
    static constexpr std::size_t find() noexcept {
        constexpr bool matches[] = {std::is_same_v<T, Ts>...};
        for (std::size_t i = 0; i < sizeof...(Ts); ++i) {
            if (matches[i]) return i;
        }
        return sizeof...(Ts);
    }
    static constexpr std::size_t value = find();
    static_assert(value < sizeof...(Ts), "type is not an alternative of the variant");
};
} // namespace detail

/// Index of a shape type in shapes_variant_t, e.g. to store which component a body's shape is:
/// `shapes_variant_t(shape).index() == get_shape_index<decltype(shape)>()`.
/// @tparam Shape One of the shape types; any other type fails to compile.
template<typename Shape>
constexpr std::size_t get_shape_index() noexcept {
    return detail::variant_index<Shape, shapes_variant_t>::value;
}

/// Number of shape types in shapes_variant_t.
inline constexpr std::size_t num_shapes = std::variant_size_v<shapes_variant_t>;

/// Whether `Shape` is one that only static (and, for meshes, kinematic) bodies may have: planes
/// and meshes, with no volume or inertia, and no collision between two of them.
template<typename Shape>
inline constexpr bool is_static_only_shape_v =
    std::is_same_v<Shape, plane_shape> || std::is_same_v<Shape, mesh_shape> ||
    std::is_same_v<Shape, paged_mesh_shape>;

/// Whether `Shape` is made of several convex pieces (children, triangles), each of which may
/// touch another shape at its own place.
template<typename Shape>
inline constexpr bool is_composite_shape_v =
    std::is_same_v<Shape, compound_shape> || std::is_same_v<Shape, mesh_shape> ||
    std::is_same_v<Shape, paged_mesh_shape>;

/// Whether shapes A and B touch at one point at most: a sphere and a convex shape (a plane
/// included) meet where the sphere's centre is nearest the other shape, and nowhere else.
template<typename A, typename B>
inline constexpr bool touches_at_one_point_v = (std::is_same_v<A, sphere_shape> &&
                                                !is_composite_shape_v<B>) ||
                                               (std::is_same_v<B, sphere_shape> && !is_composite_shape_v<A>);

/// Matches shapes_variant_t only.
///
/// Functions overloaded for every shape take the variant through this constraint rather than by
/// conversion, so that a shape type lacking its own overload is a compile error instead of a
/// conversion to the variant and an endless recursion.
template<typename T>
concept shapes_variant = std::same_as<T, shapes_variant_t>;

} // namespace edyn

#endif // EDYN_SHAPES_SHAPES_HPP
