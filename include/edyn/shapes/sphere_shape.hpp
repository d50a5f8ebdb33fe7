#ifndef EDYN_SHAPES_SPHERE_SHAPE_HPP
#define EDYN_SHAPES_SPHERE_SHAPE_HPP

#include "edyn/math/scalar.hpp"

namespace edyn {

/// Sphere centred at the origin of its object space, a shape for rigid bodies of any kind.
///
/// It has no features: collision points and raycasts report none (std::monostate).
struct sphere_shape {
    scalar radius; ///< Radius (m); positive and finite (see validate_shape()).
};

} // namespace edyn

#endif // EDYN_SHAPES_SPHERE_SHAPE_HPP
