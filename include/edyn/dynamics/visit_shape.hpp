#ifndef EDYN_DYNAMICS_VISIT_SHAPE_HPP
#define EDYN_DYNAMICS_VISIT_SHAPE_HPP

#include "edyn/config/assert.hpp"
#include "edyn/dynamics/shape_index.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/shapes/shapes.hpp"
#include <utility>

namespace edyn {

/// A body's shape component without its type: the component's address and its type's index in
/// shapes_variant_t (the body's shape_index). What visit_shape reads, for loops that gather it
/// once and visit it many times without looking the body up again. Valid until a shape
/// component of that type is added to or removed from any entity.
struct shape_ref {
    const void *shape{nullptr}; ///< The shape component.
    std::size_t index{0};       ///< Its type's index in shapes_variant_t.
};

/// Calls `fn(const Shape &)` with the shape `ref` stands for.
/// @tparam Fn A callable taking `const S &` for every shape type `S` of shapes_variant_t, and
/// returning the same type for all of them.
/// @param ref A shape component and its type's index.
/// @param fn The function to call with the shape.
/// @return Whatever `fn` returns.
template<typename Fn>
decltype(auto) visit_shape(shape_ref ref, Fn &&fn) {
    EDYN_ASSERT(ref.shape && ref.index < num_shapes);
    return [&]<std::size_t... I>(std::index_sequence<I...>)->decltype(auto) {
        using result_t =
            decltype(fn(std::declval<const std::variant_alternative_t<0, shapes_variant_t> &>()));
        using table_t = result_t (*)(const void *, Fn &);
        static constexpr table_t table[] = {[](const void *shape, Fn &f) -> result_t {
            return f(*static_cast<const std::variant_alternative_t<I, shapes_variant_t> *>(shape));
        }...};
        return table[ref.index](ref.shape, fn);
    }
    (std::make_index_sequence<num_shapes>{});
}

/// The shape component of `entity`, as visit_shape reads it.
/// The entity must have a shape_index (any rigid body with a shape); this is not checked, other
/// than by assertions in debug builds.
/// @param registry The registry the body lives in.
/// @param entity A body with a shape.
/// @return Its shape component and that component's type index.
inline shape_ref get_shape_ref(const registry &registry, entity entity) {
    auto index = registry.get<shape_index>(entity).value;
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        using table_t = const void *(*)(const edyn::registry &, edyn::entity);
        static constexpr table_t table[] = {[](const edyn::registry &reg, edyn::entity e) -> const void * {
            return &reg.get<std::variant_alternative_t<I, shapes_variant_t>>(e);
        }...};
        return shape_ref{table[index](registry, entity), index};
    }
    (std::make_index_sequence<num_shapes>{});
}

/// Calls `fn(const Shape &)` with the shape component of `entity`, without copying it into a
/// variant.
/// The entity must have a shape_index (any rigid body with a shape); this is not checked, other
/// than by assertions in debug builds.
/// @tparam Fn A callable taking `const S &` for every shape type `S` of shapes_variant_t, and
/// returning the same type for all of them.
/// @param registry The registry the body lives in.
/// @param entity A body with a shape.
/// @param fn The function to call with the shape.
/// @return Whatever `fn` returns.
template<typename Fn>
decltype(auto) visit_shape(const registry &registry, entity entity, Fn &&fn) {
    return visit_shape(get_shape_ref(registry, entity), std::forward<Fn>(fn));
}

} // namespace edyn

#endif // EDYN_DYNAMICS_VISIT_SHAPE_HPP
