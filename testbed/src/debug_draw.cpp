#include "debug_draw.hpp"
#include <algorithm>

namespace testbed {

void add_line(renderer &r, const edyn::vector3 &a, const edyn::vector3 &b, float red, float green,
              float blue) {
    r.lines.push_back({float(a.x), float(a.y), float(a.z), red, green, blue});
    r.lines.push_back({float(b.x), float(b.y), float(b.z), red, green, blue});
}

void add_cross(renderer &r, const edyn::vector3 &p, float size, float red, float green, float blue) {
    auto s = edyn::scalar(size);
    add_line(r, p - edyn::vector3{s, 0, 0}, p + edyn::vector3{s, 0, 0}, red, green, blue);
    add_line(r, p - edyn::vector3{0, s, 0}, p + edyn::vector3{0, s, 0}, red, green, blue);
    add_line(r, p - edyn::vector3{0, 0, s}, p + edyn::vector3{0, 0, s}, red, green, blue);
}

void add_box(renderer &r, const edyn::AABB &box, float red, float green, float blue) {
    auto corner = [&](int i) {
        return edyn::vector3{i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                             i & 4 ? box.max.z : box.min.z};
    };
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) add_line(r, corner(i), corner(i | bit), red, green, blue);
}

namespace {

void draw_contacts(const edyn::registry &registry, renderer &r, const debug_options &options) {
    registry.view<edyn::contact_manifold>().each([&](const edyn::contact_manifold &manifold) {
        manifold.each_point([&](const edyn::contact_point &cp) {
            if (options.contacts) add_cross(r, cp.positionB, 0.05f, 1.0f, 0.9f, 0.1f);
            if (options.normals)
                add_line(r, cp.positionB, cp.positionB + cp.normal * edyn::scalar(0.4), 1.0f, 0.3f, 0.1f);
        });
    });
}

void draw_islands(const edyn::registry &registry, renderer &r) {
    for (auto island_entity : registry.view<edyn::island>()) {
        auto &isl = registry.get<edyn::island>(island_entity);
        edyn::AABB bounds{};
        bool any = false;
        for (auto node : isl.nodes) {
            auto *box = registry.try_get<edyn::AABB>(node);
            if (!box) continue;
            bounds = any ? edyn::enclosing_aabb(bounds, *box) : *box;
            any = true;
        }
        if (!any) continue;
        if (registry.all_of<edyn::sleeping_tag>(island_entity)) {
            add_box(r, bounds, 0.5f, 0.5f, 0.5f);
        } else {
            add_box(r, bounds, 0.2f, 0.9f, 0.4f);
        }
    }
}

} // namespace

void draw_debug(const edyn::registry &registry, renderer &r, const debug_options &options) {
    if (options.contacts || options.normals) draw_contacts(registry, r, options);
    if (options.aabbs) {
        for (auto e : registry.view<edyn::rigidbody_tag, edyn::AABB>()) {
            if (registry.all_of<edyn::static_tag>(e) && registry.all_of<edyn::plane_shape>(e)) continue;
            add_box(r, registry.get<edyn::AABB>(e), 0.9f, 0.9f, 0.9f);
        }
    }
    if (options.islands) draw_islands(registry, r);
}

} // namespace testbed
