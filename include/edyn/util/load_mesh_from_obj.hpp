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

/// Loads all faces of an OBJ file as one triangle list, for a triangle mesh.
///
/// Faces are triangulated (a polygon becomes a fan) and every vertex is transformed as
/// `pos + orn * (scale * v)`. Vertex colours written after a vertex's coordinates
/// (`v x y z r g b`) are returned in [0, 1], white where the file has none; used with triangle
/// meshes, red is read as friction and green as restitution.
/// @param path Path of the .obj file.
/// @param vertices Receives every vertex of the file, in file order (cleared first).
/// @param indices Receives three vertex indices per triangle (cleared first).
/// @param colors When not null, receives one colour per vertex (cleared first).
/// @param pos Translation applied to every vertex, in metres.
/// @param orn Rotation applied to every vertex (x y z w); must be unit length.
/// @param scale Scale applied to every vertex per axis, before the rotation; finite and > 0.
/// @return False, with the outputs left empty, when the file cannot be opened or read, is
/// malformed (as the parser reports, or a face names a vertex that does not exist), has a
/// non-finite coordinate, or holds no face.
/// @throws std::invalid_argument When `scale` is not finite and positive or `orn` is not a unit
/// quaternion (whatever the file).
bool load_tri_mesh_from_obj(const std::string &path, std::vector<vector3> &vertices,
                            std::vector<std::uint32_t> &indices, std::vector<vector3> *colors = nullptr,
                            const vector3 &pos = vector3_zero, const quaternion &orn = quaternion_identity,
                            const vector3 &scale = vector3_one);

/// One object (`o`) or group (`g`) of an OBJ file, with only the vertices its faces use; filled
/// by load_meshes_from_obj.
struct obj_mesh {
    std::string name;                   ///< The object's or group's name in the file.
    std::vector<vector3> vertices;      ///< Its vertices, transformed, in order of first use.
    std::vector<std::uint32_t> indices; ///< Three indices into `vertices` per triangle.
    std::vector<vector3> colors;        ///< One colour per vertex, in [0, 1] (white where the file has none).
};

/// Loads each object of an OBJ file as its own triangle list, in file order; objects without
/// faces are skipped. Faces are triangulated and vertices transformed as by
/// load_tri_mesh_from_obj.
/// @param path Path of the .obj file.
/// @param meshes Receives the objects (cleared first).
/// @param pos Translation applied to every vertex, in metres.
/// @param orn Rotation applied to every vertex (x y z w); must be unit length.
/// @param scale Scale applied to every vertex per axis, before the rotation; finite and > 0.
/// @return False, with `meshes` left empty, for a file load_tri_mesh_from_obj would refuse.
/// @throws std::invalid_argument When `scale` is not finite and positive or `orn` is not a unit
/// quaternion (whatever the file).
bool load_meshes_from_obj(const std::string &path, std::vector<obj_mesh> &meshes,
                          const vector3 &pos = vector3_zero, const quaternion &orn = quaternion_identity,
                          const vector3 &scale = vector3_one);

/// Loads an OBJ file as a convex polyhedron: the convex hull of every vertex the file's faces
/// use, transformed as by load_tri_mesh_from_obj.
/// @param path Path of the .obj file.
/// @param pos Translation applied to every vertex, in metres.
/// @param orn Rotation applied to every vertex (x y z w); must be unit length.
/// @param scale Scale applied to every vertex per axis, before the rotation; finite and > 0.
/// @return The polyhedron; nullopt for a file load_tri_mesh_from_obj would refuse, or when the
/// vertices span no volume (the polyhedron cannot be made).
/// @throws std::invalid_argument When `scale` is not finite and positive or `orn` is not a unit
/// quaternion (whatever the file).
std::optional<polyhedron_shape> load_polyhedron_from_obj(const std::string &path,
                                                         const vector3 &pos = vector3_zero,
                                                         const quaternion &orn = quaternion_identity,
                                                         const vector3 &scale = vector3_one);

/// Loads an OBJ file as a compound shape with one convex child per object: the convex hull of
/// the object's vertices, placed at the hull's centroid. The compound is finished.
/// @param path Path of the .obj file.
/// @param pos Translation applied to every vertex, in metres.
/// @param orn Rotation applied to every vertex (x y z w); must be unit length.
/// @param scale Scale applied to every vertex per axis, before the rotation; finite and > 0.
/// @return The compound; nullopt for a file load_tri_mesh_from_obj would refuse, or when an
/// object's vertices span no volume.
/// @throws std::invalid_argument When `scale` is not finite and positive or `orn` is not a unit
/// quaternion (whatever the file).
std::optional<compound_shape> load_compound_from_obj(const std::string &path,
                                                     const vector3 &pos = vector3_zero,
                                                     const quaternion &orn = quaternion_identity,
                                                     const vector3 &scale = vector3_one);

} // namespace edyn

#endif // EDYN_UTIL_LOAD_MESH_FROM_OBJ_HPP
