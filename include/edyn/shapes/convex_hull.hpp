#ifndef EDYN_SHAPES_CONVEX_HULL_HPP
#define EDYN_SHAPES_CONVEX_HULL_HPP

#include "edyn/shapes/convex_mesh.hpp"
#include <span>

namespace edyn {

/// Convex hull of a point cloud by 3D quickhull, computed in double precision.
///
/// Points closer than a tolerance to the hull's surface (interior, duplicate and coplanar points,
/// points in the middle of an edge) do not become vertices. Triangles that lie in one plane
/// within that tolerance are merged into one polygonal face, so the hull of a cube's corners (and
/// of any points on its faces) has 6 quadrilateral faces. The tolerance is a few roundings of
/// the cloud's largest coordinate: 3 scalar epsilons times the largest absolute coordinate (in
/// double builds at least 750 double epsilons), and faces merge within twice that.
///
/// The vertices of the result are input points, in input order. polyhedron_shape's constructor
/// from points calls it.
/// @param points The point cloud (m).
/// @return A validated convex mesh with all derived data filled.
/// @throws std::invalid_argument Naming convex_hull, when a point is not finite or when the points
///         do not span a volume (fewer than 4 points, or all coincident, collinear or coplanar
///         within the tolerance); naming polyhedron_shape should the hull fail the final
///         validation of make_convex_mesh().
convex_mesh convex_hull(std::span<const vector3> points);

} // namespace edyn

#endif // EDYN_SHAPES_CONVEX_HULL_HPP
