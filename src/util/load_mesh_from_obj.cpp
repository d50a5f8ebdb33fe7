#include "edyn/util/load_mesh_from_obj.hpp"
#include "edyn/math/transform.hpp"
#include "edyn/shapes/moment_of_inertia.hpp"
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tiny_obj_loader.h>

namespace edyn {

namespace {

void check_transform(const char *fn, const quaternion &orn, const vector3 &scale) {
    if (!isfinite(scale) || !(scale.x > 0 && scale.y > 0 && scale.z > 0)) {
        throw std::invalid_argument(std::string(fn) + ": scale must be finite and positive");
    }
    if (!isfinite(orn) || !is_unit(orn)) {
        throw std::invalid_argument(std::string(fn) + ": orientation must be a unit quaternion");
    }
}

struct obj_file {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
};

// Parses the file and checks what the parser leaves to its caller: indices in range, finite
// coordinates, at least one face.
bool parse(const std::string &path, obj_file &file) {
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    bool ok = false;
    try {
        ok = tinyobj::LoadObj(&file.attrib, &file.shapes, &materials, &warn, &err, path.c_str(), nullptr,
                              true, true);
    } catch (...) {
        return false;
    }
    if (!ok) return false;
    const auto &v = file.attrib.vertices;
    if (v.size() % 3 != 0) return false;
    for (auto x : v) {
        if (!std::isfinite(x)) return false;
    }
    auto num_vertices = v.size() / 3;
    if (file.attrib.colors.size() != v.size()) file.attrib.colors.assign(v.size(), 1.0f);
    std::size_t faces = 0;
    for (const auto &shape : file.shapes) {
        const auto &mesh = shape.mesh;
        if (mesh.indices.size() % 3 != 0) return false;
        for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
            if (mesh.num_face_vertices[f] != 3) return false;
        }
        for (const auto &index : mesh.indices) {
            if (index.vertex_index < 0 || std::size_t(index.vertex_index) >= num_vertices) return false;
        }
        faces += mesh.indices.size() / 3;
    }
    return faces > 0;
}

vector3 vertex_of(const obj_file &file, std::size_t i, const vector3 &pos, const quaternion &orn,
                  const vector3 &scale) {
    const auto *v = &file.attrib.vertices[i * 3];
    auto local = vector3{scalar(v[0]), scalar(v[1]), scalar(v[2])} * scale;
    return to_world_space(local, pos, orn);
}

vector3 color_of(const obj_file &file, std::size_t i) {
    const auto *c = &file.attrib.colors[i * 3];
    return {scalar(c[0]), scalar(c[1]), scalar(c[2])};
}

// One object's faces, with its vertices renumbered in order of first use.
obj_mesh object_mesh(const obj_file &file, const tinyobj::shape_t &shape, const vector3 &pos,
                     const quaternion &orn, const vector3 &scale) {
    obj_mesh m;
    m.name = shape.name;
    std::map<int, std::uint32_t> renumbered;
    for (const auto &index : shape.mesh.indices) {
        auto [it, inserted] = renumbered.try_emplace(index.vertex_index, std::uint32_t(m.vertices.size()));
        if (inserted) {
            m.vertices.push_back(vertex_of(file, std::size_t(index.vertex_index), pos, orn, scale));
            m.colors.push_back(color_of(file, std::size_t(index.vertex_index)));
        }
        m.indices.push_back(it->second);
    }
    return m;
}

} // namespace

bool load_tri_mesh_from_obj(const std::string &path, std::vector<vector3> &vertices,
                            std::vector<std::uint32_t> &indices, std::vector<vector3> *colors,
                            const vector3 &pos, const quaternion &orn, const vector3 &scale) {
    check_transform("load_tri_mesh_from_obj", orn, scale);
    vertices.clear();
    indices.clear();
    if (colors) colors->clear();
    obj_file file;
    if (!parse(path, file)) return false;
    auto num_vertices = file.attrib.vertices.size() / 3;
    for (std::size_t i = 0; i < num_vertices; ++i) {
        vertices.push_back(vertex_of(file, i, pos, orn, scale));
        if (colors) colors->push_back(color_of(file, i));
    }
    for (const auto &shape : file.shapes) {
        for (const auto &index : shape.mesh.indices)
            indices.push_back(std::uint32_t(index.vertex_index));
    }
    return true;
}

bool load_meshes_from_obj(const std::string &path, std::vector<obj_mesh> &meshes, const vector3 &pos,
                          const quaternion &orn, const vector3 &scale) {
    check_transform("load_meshes_from_obj", orn, scale);
    meshes.clear();
    obj_file file;
    if (!parse(path, file)) return false;
    for (const auto &shape : file.shapes) {
        if (shape.mesh.indices.empty()) continue;
        meshes.push_back(object_mesh(file, shape, pos, orn, scale));
    }
    return true;
}

std::optional<polyhedron_shape> load_polyhedron_from_obj(const std::string &path, const vector3 &pos,
                                                         const quaternion &orn, const vector3 &scale) {
    std::vector<vector3> vertices;
    std::vector<std::uint32_t> indices;
    if (!load_tri_mesh_from_obj(path, vertices, indices, nullptr, pos, orn, scale)) return std::nullopt;
    std::vector<vector3> used;
    std::vector<bool> seen(vertices.size(), false);
    for (auto i : indices) {
        if (!seen[i]) {
            seen[i] = true;
            used.push_back(vertices[i]);
        }
    }
    try {
        return polyhedron_shape(used);
    } catch (const std::invalid_argument &) {
        return std::nullopt;
    }
}

std::optional<compound_shape> load_compound_from_obj(const std::string &path, const vector3 &pos,
                                                     const quaternion &orn, const vector3 &scale) {
    std::vector<obj_mesh> meshes;
    if (!load_meshes_from_obj(path, meshes, pos, orn, scale)) return std::nullopt;
    compound_shape compound;
    try {
        for (const auto &m : meshes) {
            auto hull = polyhedron_shape(m.vertices);
            // Centred on its centroid, so that the child's origin is its centre.
            auto centroid = shape_centroid(hull);
            std::vector<vector3> centred;
            for (const auto &v : m.vertices)
                centred.push_back(v - centroid);
            compound.add_shape(polyhedron_shape(centred), centroid);
        }
        compound.finish();
    } catch (const std::invalid_argument &) {
        return std::nullopt;
    }
    return compound;
}

} // namespace edyn
