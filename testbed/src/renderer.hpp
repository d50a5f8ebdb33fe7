// Draws lit shapes and debug lines with OpenGL 3.3 core. Bodies of one mesh kind (boxes,
// spheres, cylinders, planes) are drawn with one instanced draw call; convex polyhedra, each of
// its own geometry, are transformed on the CPU into one batch and drawn with one call; triangle
// meshes keep their vertices on the GPU and are drawn once each.
#ifndef EDYN_TESTBED_RENDERER_HPP
#define EDYN_TESTBED_RENDERER_HPP

#include "gl.hpp"
#include "math3d.hpp"
#include "shape_meshes.hpp"
#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <vector>

namespace testbed {

enum class mesh_kind : std::uint8_t { box, sphere, cylinder, plane, count };

// One drawn copy of a unit mesh: a position, an orientation (x y z w), a scale per object axis
// and a colour.
struct instance {
    float pos[3];
    float quat[4];
    float scale[3];
    float colour[3];
};

// A vertex of the polyhedron batch and of triangle meshes: world (or object) space, its colour.
struct coloured_vertex {
    float px, py, pz;
    float nx, ny, nz;
    float r, g, b;
};

struct line_vertex {
    float x, y, z;
    float r, g, b;
};

class renderer {
public:
    renderer();
    ~renderer();
    renderer(const renderer &) = delete;
    renderer &operator=(const renderer &) = delete;

    // Clears the frame, to be filled by the lists below and then drawn by draw().
    void begin(const mat4 &view_projection, int width, int height);

    std::array<std::vector<instance>, std::size_t(mesh_kind::count)> instances;
    std::vector<coloured_vertex> polyhedra;
    std::vector<line_vertex> lines;
    // A static triangle mesh drawn at a body's transform (its vertices uploaded once).
    void add_triangle_mesh(const edyn::triangle_mesh &mesh, const instance &transform);
    // A page of a paged mesh: uploaded the first time it is seen loaded (`loaded` not null),
    // drawn from then on, also while the simulation has it unloaded again. Pages never seen
    // loaded are not drawn.
    void add_mesh_page(const edyn::paged_triangle_mesh &mesh, std::size_t page,
                       const edyn::triangle_mesh *loaded, const instance &transform);
    // Drops the uploaded meshes, whose owners are gone (a new sample).
    void forget_meshes();

    void draw();
    // Draw calls issued by the last draw().
    int draw_calls() const { return last_draw_calls; }

private:
    struct gpu_mesh {
        unsigned vao{0}, vbo{0}, ibo{0};
        int index_count{0};
    };
    struct gpu_trimesh {
        unsigned vao{0}, vbo{0};
        int vertex_count{0};
    };
    unsigned lit_program{0}, line_program{0};
    std::array<gpu_mesh, std::size_t(mesh_kind::count)> meshes{};
    unsigned instance_vbo{0};
    unsigned batch_vao{0}, batch_vbo{0};
    unsigned line_vao{0}, line_vbo{0};
    // By owner and page (a mesh_shape's mesh is page 0 of itself).
    std::map<std::pair<const void *, std::size_t>, gpu_trimesh> trimeshes;
    std::vector<std::pair<const gpu_trimesh *, instance>> trimesh_draws;
    mat4 view_projection;
    int last_draw_calls{0};

    gpu_mesh upload(const std::vector<mesh_vertex> &vertices);
    gpu_trimesh upload(const edyn::triangle_mesh &mesh);
    void draw_lit(unsigned vao, int count, int instances, bool checker);
};

} // namespace testbed

#endif // EDYN_TESTBED_RENDERER_HPP
