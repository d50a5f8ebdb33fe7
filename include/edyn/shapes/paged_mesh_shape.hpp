#ifndef EDYN_SHAPES_PAGED_MESH_SHAPE_HPP
#define EDYN_SHAPES_PAGED_MESH_SHAPE_HPP

#include "edyn/shapes/paged_triangle_mesh.hpp"
#include <memory>

namespace edyn {

/// A paged triangle mesh shape (see paged_triangle_mesh) for static and kinematic bodies: large
/// terrain whose pages load on demand. Otherwise as mesh_shape.
struct paged_mesh_shape {
    /// The shared paged mesh, usually made by create_paged_triangle_mesh(); must not be null.
    std::shared_ptr<paged_triangle_mesh> trimesh;
};

} // namespace edyn

#endif // EDYN_SHAPES_PAGED_MESH_SHAPE_HPP
