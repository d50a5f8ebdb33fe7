// Triangle lists for the shapes, in object space with flat or smooth normals: the unit meshes
// that instances scale (box, sphere, cylinder, plane quad) and the meshes built once from a
// body's own geometry (convex polyhedra, triangle meshes).
#ifndef EDYN_TESTBED_SHAPE_MESHES_HPP
#define EDYN_TESTBED_SHAPE_MESHES_HPP

#include <edyn/edyn.hpp>
#include <vector>

namespace testbed {

struct mesh_vertex {
    float px, py, pz;
    float nx, ny, nz;
};

// Half extents 1.
std::vector<mesh_vertex> make_box_mesh();
// Radius 1.
std::vector<mesh_vertex> make_sphere_mesh(int rings = 8, int segments = 14);
// Radius 1, from x = -1 to 1, with caps.
std::vector<mesh_vertex> make_cylinder_mesh(int segments = 16);
// The square from -1 to 1 in x and z, facing +y.
std::vector<mesh_vertex> make_quad_mesh();
// Every face fanned into triangles, flat normals.
std::vector<mesh_vertex> make_polyhedron_mesh(const edyn::convex_mesh &mesh);
// Every triangle, flat normals.
std::vector<mesh_vertex> make_triangle_mesh(const edyn::triangle_mesh &mesh);

} // namespace testbed

#endif // EDYN_TESTBED_SHAPE_MESHES_HPP
