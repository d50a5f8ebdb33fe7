#ifndef EDYN_SHAPES_MESH_SHAPE_HPP
#define EDYN_SHAPES_MESH_SHAPE_HPP

#include "edyn/shapes/triangle_mesh.hpp"
#include <memory>

namespace edyn {

/// Concave triangle mesh shape (see triangle_mesh), for static and kinematic bodies only.
///
/// It has no volume, mass or inertia, and nothing collides with it but convex shapes and
/// compounds. Unlike a plane, it follows its body's position and orientation (the mesh's vertices
/// are in the body's object space). The mesh is shared, so copying the shape copies a pointer; it
/// must be initialized before the shape is given to a body.
struct mesh_shape {
    /// The shared, initialized triangle mesh; must not be null (see validate_shape()).
    std::shared_ptr<triangle_mesh> trimesh;
};

} // namespace edyn

#endif // EDYN_SHAPES_MESH_SHAPE_HPP
