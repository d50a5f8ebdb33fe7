#ifndef EDYN_UTIL_LOAD_MESH_FROM_OBJ_HPP
#define EDYN_UTIL_LOAD_MESH_FROM_OBJ_HPP

#include "edyn/math/quaternion.hpp"
#include "edyn/shapes/compound_shape.hpp"
#include "edyn/shapes/polyhedron_shape.hpp"
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace edyn {

// Wavefront OBJ loading. Faces are triangulated (a polygon becomes a fan), every vertex is
// transformed as pos + orn * (scale * v), and vertex colours written after a vertex's
// coordinates (`v x y z r g b`, an unofficial but common extension) are returned in [0, 1]
// (white where the file has none). Used with triangle meshes, red is read as friction and green
// as restitution (see the manual's per-vertex materials).
//
// Every function returns false (or nullopt) and leaves its outputs empty when the file cannot
// be opened or read, is malformed (as the parser reports, or a face names a vertex that does
// not exist), has a non-finite coordinate, or holds no face; none throws for a bad file.

// All faces of the file as one triangle list: vertices, three indices per triangle and, when
// `colors` is given, one colour per vertex. Throws std::invalid_argument when scale is not
// finite and positive or orn not unit length.
bool load_tri_mesh_from_obj(const std::string &path, std::vector<vector3> &vertices,
                            std::vector<std::uint32_t> &indices, std::vector<vector3> *colors = nullptr,
                            const vector3 &pos = vector3_zero, const quaternion &orn = quaternion_identity,
                            const vector3 &scale = vector3_one);

// One object (`o`) or group (`g`) of an OBJ file, with only the vertices its faces use.
struct obj_mesh {
    std::string name;
    std::vector<vector3> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<vector3> colors;
};

// Each object of the file as its own triangle list, in file order.
bool load_meshes_from_obj(const std::string &path, std::vector<obj_mesh> &meshes,
                          const vector3 &pos = vector3_zero, const quaternion &orn = quaternion_identity,
                          const vector3 &scale = vector3_one);

// A convex polyhedron: the convex hull of every vertex the file's faces use.
std::optional<polyhedron_shape> load_polyhedron_from_obj(const std::string &path,
                                                         const vector3 &pos = vector3_zero,
                                                         const quaternion &orn = quaternion_identity,
                                                         const vector3 &scale = vector3_one);

// A compound with one convex child per object: the convex hull of the object's vertices,
// placed at the hull's centroid. nullopt also when an object's vertices span no volume.
std::optional<compound_shape> load_compound_from_obj(const std::string &path,
                                                     const vector3 &pos = vector3_zero,
                                                     const quaternion &orn = quaternion_identity,
                                                     const vector3 &scale = vector3_one);

} // namespace edyn

#endif // EDYN_UTIL_LOAD_MESH_FROM_OBJ_HPP
