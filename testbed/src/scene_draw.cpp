#include "scene_draw.hpp"
#include "body_colour.hpp"
#include <edyn/dynamics/visit_shape.hpp>

namespace testbed {

namespace {

struct transform {
    edyn::vector3 pos;
    edyn::quaternion orn;
};

transform compose(const transform &parent, const edyn::vector3 &pos, const edyn::quaternion &orn) {
    return {parent.pos + edyn::rotate(parent.orn, pos), parent.orn * orn};
}

instance make_instance(const transform &t, const edyn::vector3 &scale, colour c) {
    return {{float(t.pos.x), float(t.pos.y), float(t.pos.z)},
            {float(t.orn.x), float(t.orn.y), float(t.orn.z), float(t.orn.w)},
            {float(scale.x), float(scale.y), float(scale.z)},
            {c.r, c.g, c.b}};
}

// The unit cylinder and the capsule's segment lie along x: this turns x onto the shape's axis.
edyn::quaternion axis_rotation(edyn::coordinate_axis axis) {
    switch (axis) {
    case edyn::coordinate_axis::y:
        return edyn::quaternion_axis_angle(edyn::vector3_z, edyn::pi / 2);
    case edyn::coordinate_axis::z:
        return edyn::quaternion_axis_angle(edyn::vector3_y, -edyn::pi / 2);
    default:
        return edyn::quaternion_identity;
    }
}

struct shape_drawer {
    renderer &r;
    transform t;
    colour c;
    bool read_pages; // false in asynchronous mode, where the worker loads and unloads them

    void add(mesh_kind kind, const transform &at, const edyn::vector3 &scale) {
        r.instances[std::size_t(kind)].push_back(make_instance(at, scale, c));
    }

    void operator()(const edyn::box_shape &s) { add(mesh_kind::box, t, s.half_extents); }
    void operator()(const edyn::sphere_shape &s) {
        add(mesh_kind::sphere, t, {s.radius, s.radius, s.radius});
    }
    void operator()(const edyn::cylinder_shape &s) {
        add(mesh_kind::cylinder, compose(t, edyn::vector3_zero, axis_rotation(s.axis)),
            {s.half_length, s.radius, s.radius});
    }
    void operator()(const edyn::capsule_shape &s) {
        auto along = compose(t, edyn::vector3_zero, axis_rotation(s.axis));
        add(mesh_kind::cylinder, along, {s.half_length, s.radius, s.radius});
        for (auto side : {-s.half_length, s.half_length})
            add(mesh_kind::sphere, compose(along, {side, 0, 0}, edyn::quaternion_identity),
                {s.radius, s.radius, s.radius});
    }
    void operator()(const edyn::polyhedron_shape &s) {
        auto &mesh = *s.mesh;
        for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
            auto n = edyn::rotate(t.orn, mesh.normals[f]);
            auto put = [&](const edyn::vector3 &local) {
                auto p = t.pos + edyn::rotate(t.orn, local);
                r.polyhedra.push_back(
                    {float(p.x), float(p.y), float(p.z), float(n.x), float(n.y), float(n.z), c.r, c.g, c.b});
            };
            for (std::size_t i = 1; i + 1 < mesh.faces[f].count; ++i) {
                put(mesh.face_vertex(f, 0));
                put(mesh.face_vertex(f, i));
                put(mesh.face_vertex(f, i + 1));
            }
        }
    }
    void operator()(const edyn::compound_shape &s) {
        auto parent = t;
        for (auto &child : s.children) {
            t = compose(parent, child.position, child.orientation);
            std::visit(*this, child.shape);
        }
        t = parent;
    }
    void operator()(const edyn::plane_shape &s) {
        // A large square on the plane, centred on its point nearest the origin.
        transform at{s.normal * s.constant, edyn::shortest_arc(edyn::vector3_y, s.normal)};
        add(mesh_kind::plane, at, {200, 1, 200});
    }
    void operator()(const edyn::mesh_shape &s) {
        r.add_triangle_mesh(*s.trimesh, make_instance(t, {1, 1, 1}, terrain_colour));
    }
    // The pages the simulation has loaded so far (on demand, near bodies). In asynchronous mode
    // the simulation worker owns the pages and they are not read here (a sample switched to that
    // mode is rebuilt, so nothing was uploaded before either).
    void operator()(const edyn::paged_mesh_shape &s) {
        auto &mesh = *s.trimesh;
        auto at = make_instance(t, {1, 1, 1}, terrain_colour);
        for (std::size_t page = 0; page < mesh.num_pages(); ++page)
            r.add_mesh_page(mesh, page, read_pages ? mesh.get_page(page) : nullptr, at);
    }
};

} // namespace

void draw_bodies(const edyn::registry &registry, renderer &r, bool grey_sleeping) {
    auto view = registry.view<edyn::rigidbody_tag, edyn::shape_index, edyn::present_position,
                              edyn::present_orientation>();
    bool read_pages = edyn::get_settings(registry).execution_mode != edyn::execution_mode::asynchronous;
    for (auto entity : view) {
        auto &pos = registry.get<edyn::present_position>(entity);
        auto &orn = registry.get<edyn::present_orientation>(entity);
        shape_drawer drawer{r, {pos, orn}, body_colour(registry, entity, grey_sleeping), read_pages};
        edyn::visit_shape(registry, entity, [&](const auto &shape) { drawer(shape); });
    }
}

} // namespace testbed
