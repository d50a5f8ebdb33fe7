#include "renderer.hpp"
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

namespace testbed {

namespace {

// Instances place, turn and scale a unit mesh; normals are scaled by the inverse so that a
// stretched box keeps its faces' normals. The batch and triangle meshes give no instance
// attributes: they read the constant values set before their draw.
const char *lit_vertex_shader = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 i_pos;
layout(location = 3) in vec4 i_quat;
layout(location = 4) in vec3 i_scale;
layout(location = 5) in vec3 i_colour;
uniform mat4 u_view_proj;
out vec3 v_normal;
out vec3 v_colour;
out vec3 v_world;
vec3 qrot(vec4 q, vec3 v) { return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v); }
void main() {
    vec3 world = i_pos + qrot(i_quat, a_pos * i_scale);
    v_normal = qrot(i_quat, a_normal / i_scale);
    v_colour = i_colour;
    v_world = world;
    gl_Position = u_view_proj * vec4(world, 1.0);
}
)";

// A key light from above and a soft fill: every face keeps at least 40% of its colour.
const char *lit_fragment_shader = R"(#version 330 core
in vec3 v_normal;
in vec3 v_colour;
in vec3 v_world;
uniform int u_checker;
out vec4 out_colour;
void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = normalize(vec3(0.3, 0.75, 0.6));
    float diffuse = max(dot(n, light), 0.0);
    vec3 c = v_colour;
    if (u_checker == 1) {
        // Squares of a metre, fading out where they would shimmer (smaller than a pixel).
        float k = mod(floor(v_world.x) + floor(v_world.z), 2.0);
        float fade = clamp(1.5 - 2.0 * max(fwidth(v_world.x), fwidth(v_world.z)), 0.0, 1.0);
        c *= mix(0.965, 0.93 + 0.07 * k, fade);
    }
    out_colour = vec4(c * (0.4 + 0.6 * diffuse), 1.0);
}
)";

const char *line_vertex_shader = R"(#version 330 core
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_colour;
uniform mat4 u_view_proj;
out vec3 v_colour;
void main() {
    v_colour = a_colour;
    gl_Position = u_view_proj * vec4(a_pos, 1.0);
}
)";

const char *line_fragment_shader = R"(#version 330 core
in vec3 v_colour;
out vec4 out_colour;
void main() { out_colour = vec4(v_colour, 1.0); }
)";

unsigned compile(GLenum type, const char *source) {
    auto shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("shader compilation failed: ") + log);
    }
    return shader;
}

unsigned link(const char *vertex, const char *fragment) {
    auto vs = compile(GL_VERTEX_SHADER, vertex);
    auto fs = compile(GL_FRAGMENT_SHADER, fragment);
    auto program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("shader program failed to link");
    return program;
}

void *offset(std::size_t bytes) { return reinterpret_cast<void *>(bytes); }

void float_attrib(unsigned index, int size, std::size_t stride, std::size_t at, unsigned divisor = 0) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, GLsizei(stride), offset(at));
    glVertexAttribDivisor(index, divisor);
}

// Instance attributes for a draw without an instance buffer: an identity transform.
void constant_instance(const instance &i, bool with_colour) {
    glVertexAttrib3f(2, i.pos[0], i.pos[1], i.pos[2]);
    glVertexAttrib4f(3, i.quat[0], i.quat[1], i.quat[2], i.quat[3]);
    glVertexAttrib3f(4, i.scale[0], i.scale[1], i.scale[2]);
    if (with_colour) glVertexAttrib3f(5, i.colour[0], i.colour[1], i.colour[2]);
}

} // namespace

renderer::renderer() {
    lit_program = link(lit_vertex_shader, lit_fragment_shader);
    line_program = link(line_vertex_shader, line_fragment_shader);
    glGenBuffers(1, &instance_vbo);
    meshes[std::size_t(mesh_kind::box)] = upload(make_box_mesh());
    meshes[std::size_t(mesh_kind::sphere)] = upload(make_sphere_mesh());
    meshes[std::size_t(mesh_kind::cylinder)] = upload(make_cylinder_mesh());
    meshes[std::size_t(mesh_kind::plane)] = upload(make_quad_mesh());

    glGenVertexArrays(1, &batch_vao);
    glGenBuffers(1, &batch_vbo);
    glBindVertexArray(batch_vao);
    glBindBuffer(GL_ARRAY_BUFFER, batch_vbo);
    float_attrib(0, 3, sizeof(coloured_vertex), 0);
    float_attrib(1, 3, sizeof(coloured_vertex), 3 * sizeof(float));
    float_attrib(5, 3, sizeof(coloured_vertex), 6 * sizeof(float));

    glGenVertexArrays(1, &line_vao);
    glGenBuffers(1, &line_vbo);
    glBindVertexArray(line_vao);
    glBindBuffer(GL_ARRAY_BUFFER, line_vbo);
    float_attrib(0, 3, sizeof(line_vertex), 0);
    float_attrib(1, 3, sizeof(line_vertex), 3 * sizeof(float));
    glBindVertexArray(0);
}

renderer::~renderer() {
    for (auto &m : meshes) {
        glDeleteVertexArrays(1, &m.vao);
        glDeleteBuffers(1, &m.vbo);
        glDeleteBuffers(1, &m.ibo);
    }
    forget_meshes();
    unsigned buffers[] = {instance_vbo, batch_vbo, line_vbo};
    glDeleteBuffers(3, buffers);
    unsigned arrays[] = {batch_vao, line_vao};
    glDeleteVertexArrays(2, arrays);
    glDeleteProgram(lit_program);
    glDeleteProgram(line_program);
}

renderer::gpu_mesh renderer::upload(const std::vector<mesh_vertex> &triangles) {
    // Shared vertices are shaded once: a software renderer spends most of a pile's frame there.
    std::vector<mesh_vertex> vertices;
    std::vector<unsigned> indices;
    std::map<std::array<float, 6>, unsigned> seen;
    for (auto &v : triangles) {
        auto [it, added] = seen.try_emplace({v.px, v.py, v.pz, v.nx, v.ny, v.nz}, unsigned(vertices.size()));
        if (added) vertices.push_back(v);
        indices.push_back(it->second);
    }
    gpu_mesh m;
    m.index_count = int(indices.size());
    glGenVertexArrays(1, &m.vao);
    glGenBuffers(1, &m.vbo);
    glGenBuffers(1, &m.ibo);
    glBindVertexArray(m.vao);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(unsigned)), indices.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(mesh_vertex)), vertices.data(),
                 GL_STATIC_DRAW);
    float_attrib(0, 3, sizeof(mesh_vertex), 0);
    float_attrib(1, 3, sizeof(mesh_vertex), 3 * sizeof(float));
    glBindBuffer(GL_ARRAY_BUFFER, instance_vbo);
    float_attrib(2, 3, sizeof(instance), offsetof(instance, pos), 1);
    float_attrib(3, 4, sizeof(instance), offsetof(instance, quat), 1);
    float_attrib(4, 3, sizeof(instance), offsetof(instance, scale), 1);
    float_attrib(5, 3, sizeof(instance), offsetof(instance, colour), 1);
    glBindVertexArray(0);
    return m;
}

void renderer::begin(const mat4 &vp, int width, int height) {
    view_projection = vp;
    for (auto &list : instances)
        list.clear();
    polyhedra.clear();
    lines.clear();
    trimesh_draws.clear();
    glViewport(0, 0, width, height);
}

renderer::gpu_trimesh renderer::upload(const edyn::triangle_mesh &mesh) {
    auto vertices = make_triangle_mesh(mesh);
    gpu_trimesh m;
    m.vertex_count = int(vertices.size());
    glGenVertexArrays(1, &m.vao);
    glGenBuffers(1, &m.vbo);
    glBindVertexArray(m.vao);
    glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(mesh_vertex)), vertices.data(),
                 GL_STATIC_DRAW);
    float_attrib(0, 3, sizeof(mesh_vertex), 0);
    float_attrib(1, 3, sizeof(mesh_vertex), 3 * sizeof(float));
    glBindVertexArray(0);
    return m;
}

void renderer::add_triangle_mesh(const edyn::triangle_mesh &mesh, const instance &transform) {
    auto it = trimeshes.find({&mesh, 0});
    if (it == trimeshes.end()) it = trimeshes.emplace(std::pair{&mesh, std::size_t(0)}, upload(mesh)).first;
    trimesh_draws.emplace_back(&it->second, transform);
}

void renderer::add_mesh_page(const edyn::paged_triangle_mesh &mesh, std::size_t page,
                             const edyn::triangle_mesh *loaded, const instance &transform) {
    auto it = trimeshes.find({&mesh, page});
    if (it == trimeshes.end()) {
        if (!loaded) return;
        it = trimeshes.emplace(std::pair{&mesh, page}, upload(*loaded)).first;
    }
    trimesh_draws.emplace_back(&it->second, transform);
}

void renderer::forget_meshes() {
    for (auto &[key, m] : trimeshes) {
        glDeleteVertexArrays(1, &m.vao);
        glDeleteBuffers(1, &m.vbo);
    }
    trimeshes.clear();
    trimesh_draws.clear();
}

void renderer::draw_lit(unsigned vao, int count, int instance_count, bool checker) {
    glUniform1i(glGetUniformLocation(lit_program, "u_checker"), checker ? 1 : 0);
    glBindVertexArray(vao);
    if (instance_count < 0) {
        glDrawArrays(GL_TRIANGLES, 0, count);
    } else {
        glDrawElementsInstanced(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr, instance_count);
    }
    ++last_draw_calls;
}

void renderer::draw() {
    last_draw_calls = 0;
    glEnable(GL_DEPTH_TEST);
    glUseProgram(lit_program);
    glUniformMatrix4fv(glGetUniformLocation(lit_program, "u_view_proj"), 1, GL_FALSE,
                       view_projection.m.data());
    for (std::size_t k = 0; k < instances.size(); ++k) {
        auto &list = instances[k];
        if (list.empty()) continue;
        glBindBuffer(GL_ARRAY_BUFFER, instance_vbo);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(list.size() * sizeof(instance)), list.data(),
                     GL_STREAM_DRAW);
        draw_lit(meshes[k].vao, meshes[k].index_count, int(list.size()), k == std::size_t(mesh_kind::plane));
    }
    const instance identity{{0, 0, 0}, {0, 0, 0, 1}, {1, 1, 1}, {1, 1, 1}};
    if (!polyhedra.empty()) {
        glBindVertexArray(batch_vao);
        constant_instance(identity, false);
        glBindBuffer(GL_ARRAY_BUFFER, batch_vbo);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(polyhedra.size() * sizeof(coloured_vertex)),
                     polyhedra.data(), GL_STREAM_DRAW);
        draw_lit(batch_vao, int(polyhedra.size()), -1, false);
    }
    for (auto &[mesh, transform] : trimesh_draws) {
        glBindVertexArray(mesh->vao);
        constant_instance(transform, true);
        draw_lit(mesh->vao, mesh->vertex_count, -1, false);
    }
    if (!lines.empty()) {
        // Debug lines show through the bodies: contacts lie hidden between the bodies they join.
        glDisable(GL_DEPTH_TEST);
        glUseProgram(line_program);
        glUniformMatrix4fv(glGetUniformLocation(line_program, "u_view_proj"), 1, GL_FALSE,
                           view_projection.m.data());
        glBindVertexArray(line_vao);
        glBindBuffer(GL_ARRAY_BUFFER, line_vbo);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(lines.size() * sizeof(line_vertex)), lines.data(),
                     GL_STREAM_DRAW);
        glDrawArrays(GL_LINES, 0, GLsizei(lines.size()));
        ++last_draw_calls;
        glEnable(GL_DEPTH_TEST);
    }
    glBindVertexArray(0);
}

} // namespace testbed
