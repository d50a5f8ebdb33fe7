#ifndef EDYN_DYNAMICS_VISIT_SHAPE_HPP
#define EDYN_DYNAMICS_VISIT_SHAPE_HPP

#include "edyn/dynamics/shape_index.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/shapes/shapes.hpp"
#include <utility>

namespace edyn {

/// Calls `fn(const Shape &)` with the shape component of `entity`, without copying it into a
/// variant.
/// The entity must have a shape_index (any rigid body with a shape); this is not checked, other
/// than by assertions in debug builds. `fn` must accept every shape type and return the same
/// type for all of them.
/// @tparam Fn A callable taking `const S &` for every shape type `S` of shapes_variant_t.
/// @param registry The registry the body lives in.
/// @param entity A body with a shape.
/// @param fn The function to call with the shape.
/// @return Whatever `fn` returns.
template<typename Fn>
decltype(auto) visit_shape(const registry &registry, entity entity, Fn &&fn) {
    auto index = registry.get<shape_index>(entity).value;
    return [&]<std::size_t... I>(std::index_sequence<I...>)->decltype(auto) {
        using result_t =
            decltype(fn(std::declval<const std::variant_alternative_t<0, shapes_variant_t> &>()));
        using table_t = result_t (*)(const edyn::registry &, edyn::entity, Fn &);
        static constexpr table_t table[] = {[](const edyn::registry &reg, edyn::entity e, Fn &f) -> result_t {
            return f(reg.get<std::variant_alternative_t<I, shapes_variant_t>>(e));
        }...};
        return table[index](registry, entity, fn);
    }
    (std::make_index_sequence<num_shapes>{});
}

} // namespace edyn

#endif // EDYN_DYNAMICS_VISIT_SHAPE_HPP
