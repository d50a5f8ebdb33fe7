#include "edyn/collision/shape_raycast.hpp"
#include "edyn/math/transform.hpp"
#include <cmath>
#include <type_traits>

namespace edyn {

namespace {

constexpr auto infinity = std::numeric_limits<scalar>::infinity();

// The ray in a shape's object space: p0 + d t, t in [0, 1].
struct local_ray {
    vector3 p0;
    vector3 d;
};

local_ray to_local(const raycast_context &ctx) {
    auto inv = conjugate(ctx.orn);
    return {rotate(inv, ctx.p0 - ctx.pos), rotate(inv, ctx.p1 - ctx.p0)};
}

enum class ray_class { miss, inside, surface };

// The ray's line lies in the (closed) shape for t in [t_in, t_out]: the ray misses when that
// interval is empty, ends before p0 (t_out <= 0: leaving or only touching behind) or begins
// after p1; it starts inside when t_in < 0.
ray_class classify(scalar t_in, scalar t_out) {
    if (!(t_in <= t_out) || !(t_out > 0) || !(t_in <= 1)) return ray_class::miss;
    return t_in < 0 ? ray_class::inside : ray_class::surface;
}

// v / |v| without normalize()'s assertion on short vectors: rays and shapes may be tiny.
vector3 unit(const vector3 &v) { return v / length(v); }

// The result for a line that lies in the shape for t in [t_in, t_out]; normal_at_entry() gives
// the world-space normal at t_in and is called only for a hit from outside.
template<typename NormalFn>
shape_raycast_result make_result(scalar t_in, scalar t_out, const raycast_context &ctx,
                                 raycast_info_variant info, NormalFn normal_at_entry) {
    switch (classify(t_in, t_out)) {
    case ray_class::miss:
        return {};
    case ray_class::inside:
        return {0, -unit(ctx.p1 - ctx.p0), std::move(info)};
    default:
        return {t_in, normal_at_entry(), std::move(info)};
    }
}

// Interval of the line p + d t within distance r of the origin. A line with d == 0 lies in the
// sphere everywhere or nowhere.
bool sphere_interval(const vector3 &p, const vector3 &d, scalar r, scalar &t_in, scalar &t_out) {
    auto a = length_sqr(d);
    if (a == 0) {
        t_in = -infinity;
        t_out = infinity;
        return length_sqr(p) <= r * r;
    }
    // From the closest approach rather than the textbook quadratic: no cancellation when the
    // line starts far from the sphere.
    auto t_mid = -dot(p, d) / a;
    auto disc = r * r - length_sqr(p + d * t_mid);
    if (disc < 0) return false;
    auto half = std::sqrt(disc / a);
    t_in = t_mid - half;
    t_out = t_mid + half;
    return true;
}

// Interval of the line p + d t within distance r of coordinate axis k.
bool radial_interval(vector3 p, vector3 d, int k, scalar r, scalar &t_in, scalar &t_out) {
    p[k] = 0;
    d[k] = 0;
    return sphere_interval(p, d, r, t_in, t_out);
}

// Outward unit normal of a cylindrical surface about axis k at p.
vector3 radial_normal(vector3 p, int k) {
    p[k] = 0;
    auto len = length(p);
    // Only a zero radius puts a side hit on the axis.
    if (len == 0) return coordinate_axis_vector(static_cast<coordinate_axis>((k + 1) % 3));
    return p / len;
}

compound_child_raycast_info_variant to_child_info(const raycast_info_variant &info) {
    return std::visit(
        [](const auto &i) -> compound_child_raycast_info_variant {
            if constexpr (std::is_constructible_v<compound_child_raycast_info_variant, decltype(i)>) {
                return i;
            } else {
                return std::monostate{};
            }
        },
        info);
}

} // namespace

shape_raycast_result shape_raycast(const plane_shape &shape, const raycast_context &ctx) {
    if (ctx.p0 == ctx.p1) return {};
    auto dist = dot(shape.normal, ctx.p0) - shape.constant;
    auto dn = dot(shape.normal, ctx.p1 - ctx.p0);
    scalar t_in = -infinity, t_out = infinity;
    if (dn < 0) {
        t_in = -dist / dn;
    } else if (dn > 0) {
        t_out = -dist / dn;
    } else if (dist > 0) {
        return {};
    }
    return make_result(t_in, t_out, ctx, std::monostate{}, [&] { return shape.normal; });
}

shape_raycast_result shape_raycast(const sphere_shape &shape, const raycast_context &ctx) {
    if (ctx.p0 == ctx.p1) return {};
    auto p = ctx.p0 - ctx.pos;
    auto d = ctx.p1 - ctx.p0;
    scalar t_in, t_out;
    if (!sphere_interval(p, d, shape.radius, t_in, t_out)) return {};
    return make_result(t_in, t_out, ctx, std::monostate{}, [&] { return unit(p + d * t_in); });
}

shape_raycast_result shape_raycast(const box_shape &shape, const raycast_context &ctx) {
    if (ctx.p0 == ctx.p1) return {};
    auto ray = to_local(ctx);
    scalar t_in = -infinity, t_out = infinity;
    int entry_axis = 0;
    for (int i = 0; i < 3; ++i) {
        auto h = shape.half_extents[i];
        if (ray.d[i] == 0) {
            if (std::abs(ray.p0[i]) > h) return {};
            continue;
        }
        auto t_neg = (-h - ray.p0[i]) / ray.d[i];
        auto t_pos = (h - ray.p0[i]) / ray.d[i];
        auto near = std::min(t_neg, t_pos);
        if (near > t_in) {
            t_in = near;
            entry_axis = i;
        }
        t_out = std::min(t_out, std::max(t_neg, t_pos));
    }
    // Moving towards -axis, the line enters through the axis' positive face (index 2 * axis).
    auto positive = ray.d[entry_axis] < 0;
    auto info = box_raycast_info{std::size_t(2 * entry_axis + (positive ? 0 : 1))};
    return make_result(t_in, t_out, ctx, info, [&] {
        auto normal = coordinate_axis_vector(static_cast<coordinate_axis>(entry_axis));
        return rotate(ctx.orn, positive ? normal : -normal);
    });
}

shape_raycast_result shape_raycast(const cylinder_shape &shape, const raycast_context &ctx) {
    if (ctx.p0 == ctx.p1) return {};
    auto ray = to_local(ctx);
    auto k = coordinate_axis_index(shape.axis);
    scalar side_in, side_out;
    if (!radial_interval(ray.p0, ray.d, k, shape.radius, side_in, side_out)) return {};
    // Slab between the caps.
    auto h = shape.half_length;
    scalar cap_in = -infinity, cap_out = infinity;
    if (ray.d[k] == 0) {
        if (std::abs(ray.p0[k]) > h) return {};
    } else {
        auto t_neg = (-h - ray.p0[k]) / ray.d[k];
        auto t_pos = (h - ray.p0[k]) / ray.d[k];
        cap_in = std::min(t_neg, t_pos);
        cap_out = std::max(t_neg, t_pos);
    }
    auto t_in = std::max(side_in, cap_in);
    auto t_out = std::min(side_out, cap_out);
    // Caps win ties (a ray through the rim).
    auto through_side = side_in > cap_in;
    // Moving towards -axis, the line enters through the cap at +half_length (index 0).
    auto cap_index = std::size_t(ray.d[k] < 0 ? 0 : 1);
    auto info = through_side ? cylinder_raycast_info{cylinder_feature::side_edge, 0}
                             : cylinder_raycast_info{cylinder_feature::face, cap_index};
    return make_result(t_in, t_out, ctx, info, [&] {
        auto axis = coordinate_axis_vector(shape.axis);
        auto normal =
            through_side ? radial_normal(ray.p0 + ray.d * t_in, k) : (cap_index == 0 ? axis : -axis);
        return rotate(ctx.orn, normal);
    });
}

shape_raycast_result shape_raycast(const capsule_shape &shape, const raycast_context &ctx) {
    if (ctx.p0 == ctx.p1) return {};
    auto ray = to_local(ctx);
    auto k = coordinate_axis_index(shape.axis);
    auto h = shape.half_length;
    // The capsule is the union of the finite cylinder and two spheres, so the line enters it
    // at the earliest entry into a piece and leaves at the latest exit. The cylinder counts only
    // through its side: its caps lie inside the spheres.
    scalar t_in = infinity, t_out = -infinity;
    auto info = capsule_raycast_info{capsule_feature::side, 0};
    vector3 centre = vector3_zero;
    scalar a, b;
    if (radial_interval(ray.p0, ray.d, k, shape.radius, a, b) && std::isfinite(a)) {
        if (std::abs(ray.p0[k] + ray.d[k] * a) <= h) t_in = a;
        if (std::abs(ray.p0[k] + ray.d[k] * b) <= h) t_out = b;
    }
    for (std::size_t i = 0; i < 2; ++i) {
        auto c = vector3_zero;
        c[k] = i == 0 ? h : -h;
        if (!sphere_interval(ray.p0 - c, ray.d, shape.radius, a, b)) continue;
        if (a < t_in) {
            t_in = a;
            info = {capsule_feature::hemisphere, i};
            centre = c;
        }
        t_out = std::max(t_out, b);
    }
    return make_result(t_in, t_out, ctx, info, [&] {
        auto p = ray.p0 + ray.d * t_in;
        return rotate(ctx.orn,
                      info.feature == capsule_feature::side ? radial_normal(p, k) : unit(p - centre));
    });
}

shape_raycast_result shape_raycast(const polyhedron_shape &shape, const raycast_context &ctx) {
    EDYN_ASSERT(shape.mesh);
    if (ctx.p0 == ctx.p1) return {};
    auto ray = to_local(ctx);
    const auto &mesh = *shape.mesh;
    // Clip the line against every face plane (Cyrus-Beck).
    scalar t_in = -infinity, t_out = infinity;
    std::size_t entry_face = 0;
    for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
        auto dist = dot(mesh.normals[f], ray.p0) - mesh.plane_constants[f];
        auto dn = dot(mesh.normals[f], ray.d);
        if (dn == 0) {
            if (dist > 0) return {};
            continue;
        }
        auto t = -dist / dn;
        if (dn < 0) {
            if (t > t_in) {
                t_in = t;
                entry_face = f;
            }
        } else {
            t_out = std::min(t_out, t);
        }
        if (t_in > t_out) return {};
    }
    auto info = polyhedron_raycast_info{entry_face};
    return make_result(t_in, t_out, ctx, info, [&] { return rotate(ctx.orn, mesh.normals[entry_face]); });
}

namespace {

// First triangle of `mesh` along the segment [p0, p1] (mesh space), from either side.
struct triangle_hit {
    scalar fraction{raycast_miss_fraction};
    std::size_t triangle{0};
};

triangle_hit raycast_triangles(const triangle_mesh &mesh, const vector3 &p0, const vector3 &p1) {
    auto d = p1 - p0;
    triangle_hit best;
    mesh.visit_triangles_segment(p0, p1, [&](std::size_t t) {
        // Moller-Trumbore.
        auto tri = mesh.get_triangle_vertices(t);
        auto e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
        auto h = cross(d, e2);
        auto det = dot(e1, h);
        if (det == 0) return;
        auto inv = scalar(1) / det;
        auto s = p0 - tri[0];
        auto u = dot(s, h) * inv;
        if (u < 0 || u > 1) return;
        auto q = cross(s, e1);
        auto v = dot(d, q) * inv;
        if (v < 0 || u + v > 1) return;
        auto fraction = dot(e2, q) * inv;
        if (fraction < 0 || fraction > 1) return;
        if (fraction < best.fraction || (fraction == best.fraction && t < best.triangle)) {
            best.fraction = fraction;
            best.triangle = t;
        }
    });
    return best;
}

// The normal of the triangle hit, facing the ray's start, in world space.
vector3 facing_normal(const triangle_mesh &mesh, std::size_t t, const vector3 &d, const quaternion &orn) {
    auto normal = mesh.get_triangle_normal(t);
    if (dot(normal, d) > 0) normal = -normal;
    return rotate(orn, normal);
}

} // namespace

shape_raycast_result shape_raycast(const mesh_shape &shape, const raycast_context &ctx) {
    EDYN_ASSERT(shape.trimesh && shape.trimesh->initialized());
    if (ctx.p0 == ctx.p1) return {};
    auto p0 = to_object_space(ctx.p0, ctx.pos, ctx.orn);
    auto p1 = to_object_space(ctx.p1, ctx.pos, ctx.orn);
    auto hit = raycast_triangles(*shape.trimesh, p0, p1);
    if (!(hit.fraction <= 1)) return {};
    shape_raycast_result result;
    result.fraction = hit.fraction;
    result.normal = facing_normal(*shape.trimesh, hit.triangle, p1 - p0, ctx.orn);
    result.info_var = mesh_raycast_info{hit.triangle};
    return result;
}

shape_raycast_result shape_raycast(const paged_mesh_shape &shape, const raycast_context &ctx) {
    EDYN_ASSERT(shape.trimesh);
    if (ctx.p0 == ctx.p1) return {};
    auto p0 = to_object_space(ctx.p0, ctx.pos, ctx.orn);
    auto p1 = to_object_space(ctx.p1, ctx.pos, ctx.orn);
    AABB span{min(p0, p1), max(p0, p1)};
    shape_raycast_result result;
    std::size_t best_page = 0, best_triangle = 0;
    shape.trimesh->visit_loaded_pages(span, [&](std::size_t page, const triangle_mesh &mesh) {
        auto hit = raycast_triangles(mesh, p0, p1);
        if (hit.fraction < result.fraction) {
            result.fraction = hit.fraction;
            result.normal = facing_normal(mesh, hit.triangle, p1 - p0, ctx.orn);
            best_page = page;
            best_triangle = hit.triangle;
        }
    });
    if (!result.hit()) return {};
    result.info_var = paged_mesh_raycast_info{best_page, best_triangle};
    return result;
}

shape_raycast_result shape_raycast(const compound_shape &shape, const raycast_context &ctx) {
    if (ctx.p0 == ctx.p1) return {};
    // The children are placed in the compound's object space: cast there, rotate the normal back.
    auto local_p0 = to_object_space(ctx.p0, ctx.pos, ctx.orn);
    auto local_p1 = to_object_space(ctx.p1, ctx.pos, ctx.orn);
    shape_raycast_result best;
    std::size_t best_child = 0;
    shape.visit_ray(local_p0, local_p1, [&](std::size_t i) {
        const auto &child = shape.children[i];
        auto result = shape_raycast(child.shape, {child.position, child.orientation, local_p0, local_p1});
        if (!result.hit()) return;
        if (result.fraction < best.fraction || (result.fraction == best.fraction && i < best_child)) {
            best = std::move(result);
            best_child = i;
        }
    });
    if (!best.hit()) return {};
    best.normal = rotate(ctx.orn, best.normal);
    best.info_var = compound_raycast_info{best_child, to_child_info(best.info_var)};
    return best;
}

shape_raycast_result shape_raycast(const compound_child_shape_t &shape, const raycast_context &ctx) {
    return std::visit([&](const auto &s) { return shape_raycast(s, ctx); }, shape);
}

} // namespace edyn
