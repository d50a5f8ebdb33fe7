#include "edyn/collision/collide.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include "edyn/collision/detail/polyhedron_geom.hpp"
#include "edyn/collision/detail/triangle_mesh_collision.hpp"
#include "edyn/math/geom.hpp"
#include "edyn/math/math.hpp"
#include "edyn/math/transform.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include <array>
#include <cmath>

// Convex shapes against triangle meshes. Each triangle whose AABB meets the shape's (in the
// mesh's space, grown by the threshold) is made a thin prism: the triangle on top, extruded
// behind its front by its longest edge. The prism is a convex polytope, so the polyhedron pairs'
// exact routines collide the shape with it. Their points are then checked against the triangle's
// Voronoi regions: a normal other than the triangle's is kept only where the point lies on an
// active edge or vertex (a convex edge, or the mesh's boundary). Otherwise the shape touches an
// internal edge, a concave one or the prism's hidden sides, and the triangle's manifold is built
// again along the triangle's normal: the shape's supporting feature clipped to the triangle. So
// a shape crossing from one triangle to a coplanar neighbour never sees the edge between them.
namespace edyn {

namespace {

using detail::polytope;

// Topology of every triangle's prism: vertices 0..2 the triangle (counter-clockwise seen from
// the front), 3..5 the same extruded behind it. Face 0 the triangle, face 1 the back, face 2 + i
// the side through edge i (from vertex i to vertex (i + 1) % 3).
constexpr std::array<std::uint32_t, 18> prism_indices{0, 1, 2, 5, 4, 3, 0, 3, 4, 1, 1, 4, 5, 2, 2, 5, 3, 0};
constexpr std::array<convex_mesh::face_range, 5> prism_faces{{{0, 3}, {3, 3}, {6, 4}, {10, 4}, {14, 4}}};
// Front edges, back edges, then the extruded edges at each vertex; each runs from its first
// vertex to its second in its first face.
constexpr std::array<std::array<std::uint32_t, 2>, 9> prism_edges{
    {{0, 1}, {1, 2}, {2, 0}, {4, 3}, {5, 4}, {3, 5}, {0, 3}, {1, 4}, {2, 5}}};
constexpr std::array<std::array<std::uint32_t, 2>, 9> prism_edge_faces{
    {{0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}, {2, 4}, {3, 2}, {4, 3}}};

// One triangle's prism in a frame centred on the triangle's centroid and aligned with the mesh.
// Built in two parts: the triangle (its vertices and normal), then, by extrude() when a routine
// first needs them, the back, the sides and their planes. A sphere in front of the triangle, the
// commonest case on a terrain, needs only the triangle.
struct triangle_prism {
    vector3 centroid; // Mesh space.
    vector3 normal;   // Mesh space, the triangle's front.
    // Vertices 0..2 the triangle's, relative to the centroid; 3..5 filled by extrude().
    mutable std::array<vector3, 6> vertices;

    triangle_prism(const triangle_mesh &mesh, std::size_t t) noexcept {
        auto tri = mesh.get_triangle_vertices(t);
        normal = mesh.get_triangle_normal(t);
        centroid = (tri[0] + tri[1] + tri[2]) / scalar(3);
        for (int i = 0; i < 3; ++i)
            vertices[i] = tri[i] - centroid;
    }

    triangle_prism(const triangle_prism &) = delete;
    triangle_prism &operator=(const triangle_prism &) = delete;

    // The rest of the prism: behind the triangle by its longest edge.
    const triangle_prism &extrude() const noexcept {
        if (extruded) return *this;
        // One square root each for the longest edge and the farthest vertex (the root of the
        // largest square is the largest root, to the bit).
        depth =
            std::sqrt(std::max({length_sqr(vertices[1] - vertices[0]), length_sqr(vertices[2] - vertices[1]),
                                length_sqr(vertices[0] - vertices[2])}));
        scalar radius_sqr = 0;
        for (int i = 0; i < 3; ++i) {
            vertices[i + 3] = vertices[i] - normal * depth;
            radius_sqr = std::max(radius_sqr, length_sqr(vertices[i + 3]));
        }
        bounding_radius = std::sqrt(radius_sqr);
        normals[0] = normal;
        normals[1] = -normal;
        // Each edge lies in the triangle's plane, square to its unit normal: the cross product
        // of the two is a unit vector already.
        for (int i = 0; i < 3; ++i) {
            directions[i] = normalize(vertices[(i + 1) % 3] - vertices[i]);
            normals[2 + i] = cross(directions[i], normal);
        }
        directions[3] = normal;
        for (std::size_t f = 0; f < 5; ++f)
            plane_constants[f] = dot(normals[f], vertices[prism_indices[prism_faces[f].first]]);
        extruded = true;
        return *this;
    }

    // Side i's outward normal and plane constant (the side through edge i).
    const vector3 &side_normal(int i) const noexcept { return extrude().normals[2 + i]; }
    scalar side_constant(int i) const noexcept { return extrude().plane_constants[2 + i]; }
    // How far the prism reaches behind the triangle.
    scalar prism_depth() const noexcept { return extrude().depth; }

    polytope view() const noexcept {
        extrude();
        polytope p;
        p.vertices = vertices;
        p.indices = prism_indices;
        p.faces = prism_faces;
        p.normals = normals;
        p.plane_constants = plane_constants;
        p.edges = prism_edges;
        p.edge_faces = prism_edge_faces;
        p.unique_edge_directions = directions;
        p.bounding_radius = bounding_radius;
        return p;
    }

private:
    mutable bool extruded{false};
    mutable scalar depth;
    mutable std::array<vector3, 5> normals;
    mutable std::array<scalar, 5> plane_constants;
    mutable std::array<vector3, 4> directions;
    mutable scalar bounding_radius;
};

// Cosine above which a normal is the triangle's own (0.08 degrees: rounding only).
constexpr scalar face_normal_cosine = scalar(1) - scalar(1e-6);
// Barycentric tolerance of the feature classification, and how far outside its triangle a
// point along the triangle's normal may lie (relative to the triangle's size) and still count.
constexpr scalar feature_tolerance = scalar(1e-4);
constexpr scalar outside_tolerance = scalar(1e-3);

// The feature of triangle t nearest to p (mesh space), from p's barycentric coordinates.
collision_feature triangle_feature_at(std::size_t t, const vector3 &w) noexcept {
    collision_feature f;
    f.part = static_cast<std::int32_t>(t);
    int low = 0;
    std::uint32_t last_low = 0;
    for (std::uint32_t i = 0; i < 3; ++i) {
        if (w[i] <= feature_tolerance) {
            ++low;
            last_low = i;
        }
    }
    if (low == 0) {
        f.feature = triangle_feature::face;
        f.index = 0;
    } else if (low == 1) {
        // The edge opposite the vertex whose weight vanishes.
        f.feature = triangle_feature::edge;
        f.index = (last_low + 1) % 3;
    } else {
        f.feature = triangle_feature::vertex;
        f.index = w.x >= w.y && w.x >= w.z ? 0u : (w.y >= w.z ? 1u : 2u);
    }
    return f;
}

bool feature_allows_normal(const triangle_mesh &mesh, std::size_t t, const collision_feature &f,
                           const vector3 &normal_mesh) noexcept {
    auto c = dot(normal_mesh, mesh.get_triangle_normal(t));
    if (c >= face_normal_cosine) return true;
    // Only active edges and vertices give other normals, and none facing behind the triangle.
    if (c < -feature_tolerance) return false;
    auto kind = std::get<triangle_feature>(f.feature);
    if (kind == triangle_feature::edge) return mesh.is_edge_active(t, f.index);
    if (kind == triangle_feature::vertex) return mesh.is_vertex_active(t, f.index);
    return false;
}

// Whether the triangles beyond feature f of triangle t (across an edge, or across both edges
// at a vertex) are coplanar with it.
bool flat_beyond(const triangle_mesh &mesh, std::size_t t, const collision_feature &f) noexcept {
    auto coplanar = [&](std::size_t edge) {
        auto adj = mesh.get_adjacent_triangle(t, edge);
        return adj >= 0 && dot(mesh.get_triangle_normal(t), mesh.get_triangle_normal(std::size_t(adj))) >=
                               face_normal_cosine;
    };
    auto kind = std::get<triangle_feature>(f.feature);
    if (kind == triangle_feature::edge) return coplanar(f.index);
    if (kind == triangle_feature::vertex) return coplanar(f.index) && coplanar((f.index + 2) % 3);
    return true;
}

// Whether no triangle lies beyond feature f of triangle t: an edge on the mesh's boundary, or a
// vertex on one.
bool open_beyond(const triangle_mesh &mesh, std::size_t t, const collision_feature &f) noexcept {
    auto kind = std::get<triangle_feature>(f.feature);
    if (kind == triangle_feature::edge) return mesh.get_adjacent_triangle(t, f.index) < 0;
    if (kind == triangle_feature::vertex)
        return mesh.get_adjacent_triangle(t, f.index) < 0 ||
               mesh.get_adjacent_triangle(t, (f.index + 2) % 3) < 0;
    return false;
}

// Clips the convex polygon `poly` (count points, in the prism's frame) to the triangle's prism
// sides; returns the number of points left in `out`.
constexpr std::size_t max_clip_points = 64;

std::size_t clip_to_triangle(const triangle_prism &prism, const vector3 *poly, std::size_t count,
                             vector3 (&out)[max_clip_points]) noexcept {
    vector3 buffer[max_clip_points];
    const vector3 *in = poly;
    std::size_t in_count = count;
    std::size_t out_count = 0;
    for (int side = 0; side < 3; ++side) {
        auto *target = side % 2 == 0 ? out : buffer;
        out_count = 0;
        const auto &n = prism.side_normal(side);
        auto c = prism.side_constant(side);
        for (std::size_t i = 0; i < in_count; ++i) {
            const auto &p = in[i];
            const auto &q = in[(i + 1) % in_count];
            auto dp = dot(n, p) - c, dq = dot(n, q) - c;
            if (dp <= 0 && out_count < max_clip_points) target[out_count++] = p;
            if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
                if (out_count < max_clip_points) target[out_count++] = p + (q - p) * (dp / (dp - dq));
            }
        }
        in = target;
        in_count = out_count;
        if (in_count == 0) break;
    }
    // Three passes: the last wrote into `out`.
    return out_count;
}

// Where the triangle's normal is imposed: the points of the shape's supporting polygon (in the
// prism's frame) clipped to the triangle, each at its height over the triangle's plane.
void forced_polygon_points(const triangle_prism &prism, const vector3 *poly, std::size_t count,
                           const collision_context &prism_ctx, collision_result &result) noexcept {
    vector3 clipped[max_clip_points];
    auto n = clip_to_triangle(prism, poly, count, clipped);
    auto world_normal = rotate(prism_ctx.ornB, prism.normal);
    for (std::size_t i = 0; i < n; ++i) {
        auto distance = dot(clipped[i] - prism.vertices[0], prism.normal);
        if (distance > prism_ctx.threshold) continue;
        collision_result::collision_point p;
        auto world_a = to_world_space(clipped[i], prism_ctx.posB, prism_ctx.ornB);
        p.pivotA = to_object_space(world_a, prism_ctx.posA, prism_ctx.ornA);
        p.pivotB = clipped[i] - prism.normal * distance;
        p.normal = world_normal;
        p.distance = distance;
        result.add_point(p);
    }
}

// A polytope's (box's, polyhedron's) manifold along the triangle's normal.
void forced_polytope(const polytope &poly, const triangle_prism &prism, const collision_context &prism_ctx,
                     collision_result &result) noexcept {
    // The polytope in the prism's frame: x_prism = r * x_poly + t.
    auto inv_orn_b = conjugate(prism_ctx.ornB);
    auto orn = inv_orn_b * prism_ctx.ornA;
    auto pos = rotate(inv_orn_b, prism_ctx.posA - prism_ctx.posB);
    auto dir = rotate(conjugate(orn), -prism.normal);
    auto f = detail::polytope_support_feature(poly, dir);
    vector3 points[max_clip_points];
    std::size_t count = 0;
    if (f.kind == polyhedron_feature::face && poly.face_size(f.index) <= max_clip_points) {
        for (std::uint32_t k = 0; k < poly.face_size(f.index); ++k)
            points[count++] = pos + rotate(orn, poly.face_vertex(f.index, k));
    } else if (f.kind == polyhedron_feature::edge) {
        points[count++] = pos + rotate(orn, poly.vertices[poly.edges[f.index][0]]);
        points[count++] = pos + rotate(orn, poly.vertices[poly.edges[f.index][1]]);
    } else {
        points[count++] = pos + rotate(orn, poly.vertices[detail::polytope_support_vertex(poly, dir)]);
    }
    forced_polygon_points(prism, points, count, prism_ctx, result);
}

// A round shape's (sphere's, capsule's, cylinder's) manifold along the triangle's normal, from
// its supporting feature in the prism's frame: a point, a side line, or a cap facing the
// triangle, whose rim stands in as a regular polygon of 16 sides (its corners are on the rim,
// its sides within 2% of the radius inside it).
void forced_feature(const detail::contact_feature &feature, const triangle_prism &prism,
                    const collision_context &prism_ctx, collision_result &result) noexcept {
    using kind = detail::contact_feature_kind;
    vector3 points[16];
    std::size_t count = 0;
    if (feature.kind == kind::segment) {
        points[count++] = feature.vertices[0];
        points[count++] = feature.vertices[1];
    } else if (feature.kind == kind::disc) {
        vector3 u, v;
        plane_space(feature.normal, u, v);
        for (int i = 0; i < 16; ++i) {
            auto angle = scalar(i) * pi / 8;
            points[count++] = feature.center + (u * std::cos(angle) + v * std::sin(angle)) * feature.radius;
        }
    } else {
        points[count++] = feature.support;
    }
    forced_polygon_points(prism, points, count, prism_ctx, result);
}

// The shape in the prism's frame, for the supporting features of round shapes.
struct local_pose {
    vector3 pos;
    quaternion orn;
};

local_pose pose_in_prism(const collision_context &prism_ctx) noexcept {
    return {to_object_space(prism_ctx.posA, prism_ctx.posB, prism_ctx.ornB),
            conjugate(prism_ctx.ornB) * prism_ctx.ornA};
}

// The exact pair and the manifold along the triangle's normal, per shape.
void collide_prism(const sphere_shape &a, const triangle_prism &prism, const collision_context &ctx,
                   collision_result &result) {
    // A centre in front of the triangle's plane is nearest to the triangle itself (the prism lies
    // behind it): the closest point is found on the triangle directly.
    auto center = to_object_space(ctx.posA, ctx.posB, ctx.ornB);
    if (dot(center - prism.vertices[0], prism.normal) >= 0) {
        auto closest =
            closest_point_triangle(center, prism.vertices[0], prism.vertices[1], prism.vertices[2]);
        auto offset = center - closest;
        auto length_offset = length(offset);
        auto distance = length_offset - a.radius;
        if (distance > ctx.threshold) return;
        // From the triangle towards the centre: from B towards A; the face's normal for a centre
        // on the triangle.
        auto local_normal = length_offset > epsilon ? offset / length_offset : prism.normal;
        collision_result::collision_point p;
        p.normal = rotate(ctx.ornB, local_normal);
        p.pivotA = rotate(conjugate(ctx.ornA), -p.normal * a.radius);
        p.pivotB = closest;
        p.distance = distance;
        result.add_point(p);
        return;
    }
    detail::collide_swapped([](const polytope &p, const sphere_shape &s, const collision_context &c,
                               collision_result &r) { detail::collide_polytope_sphere(p, s, c, r); },
                            a, prism.view(), ctx, result);
}

void forced_prism(const sphere_shape &a, const triangle_prism &prism, const collision_context &ctx,
                  collision_result &result) {
    auto pose = pose_in_prism(ctx);
    detail::contact_feature f;
    f.kind = detail::contact_feature_kind::point;
    f.support = f.vertices[0] = pose.pos - prism.normal * a.radius;
    forced_feature(f, prism, ctx, result);
}

// The closest pair of a segment and a triangle's prism, both in the prism's frame. A segment
// wholly in front of the triangle's plane is nearest to the triangle itself, since the prism lies
// behind the plane; and as the height over the plane is linear along the segment, the pair holds
// an end of the segment over the triangle, or a point of one of the triangle's edges. Any other
// segment takes the general routine.
detail::segment_polytope_closest closest_points_segment_prism(const polytope &prism, const vector3 &p0,
                                                              const vector3 &p1) noexcept {
    auto h0 = dot(prism.normals[0], p0) - prism.plane_constants[0];
    auto h1 = dot(prism.normals[0], p1) - prism.plane_constants[0];
    if (!(h0 >= 0 && h1 >= 0)) return detail::closest_points_segment_polytope(prism, p0, p1);

    detail::segment_polytope_closest r;
    auto best_sqr = large_scalar;
    auto over_triangle = [&](const vector3 &p) {
        for (std::size_t side = 2; side < 5; ++side)
            if (dot(prism.normals[side], p) > prism.plane_constants[side]) return false;
        return true;
    };
    auto end_candidate = [&](const vector3 &p, scalar height, scalar t) {
        if (height * height >= best_sqr) return;
        best_sqr = height * height;
        r.t = t;
        r.on_segment = p;
        r.on_polytope = p - prism.normals[0] * height;
        r.feature = {polyhedron_feature::face, 0};
    };
    auto over0 = over_triangle(p0), over1 = over_triangle(p1);
    if (over0) end_candidate(p0, h0, 0);
    if (over1) end_candidate(p1, h1, 1);
    r.distance = std::sqrt(best_sqr);
    // With both ends over the triangle, all of the segment is: no edge comes nearer.
    if (over0 && over1) return r;
    // The front edges are the prism's edges 0 to 2: edge e runs from vertex e to (e + 1) % 3.
    for (std::uint32_t e = 0; e < 3; ++e) {
        auto next = (e + 1) % 3;
        auto closest = closest_points_segment_segment(p0, p1, prism.vertices[e], prism.vertices[next]);
        for (std::size_t i = 0; i < closest.num_points; ++i) {
            auto d2 = distance_sqr(closest.pointA[i], closest.pointB[i]);
            if (d2 >= best_sqr) continue;
            best_sqr = d2;
            r.t = closest.sA[i];
            r.on_segment = closest.pointA[i];
            r.on_polytope = closest.pointB[i];
            auto s = closest.sB[i];
            r.feature = s <= 0   ? detail::polytope_feature{polyhedron_feature::vertex, e}
                        : s >= 1 ? detail::polytope_feature{polyhedron_feature::vertex, next}
                                 : detail::polytope_feature{polyhedron_feature::edge, e};
        }
    }
    r.distance = std::sqrt(best_sqr);
    return r;
}

void collide_prism(const capsule_shape &a, const triangle_prism &prism, const collision_context &ctx,
                   collision_result &result) {
    detail::collide_swapped(
        [](const polytope &p, const capsule_shape &s, const collision_context &c, collision_result &r) {
            detail::collide_polytope_capsule(p, s, c, r, closest_points_segment_prism);
        },
        a, prism.view(), ctx, result);
}

void forced_prism(const capsule_shape &a, const triangle_prism &prism, const collision_context &ctx,
                  collision_result &result) {
    auto pose = pose_in_prism(ctx);
    auto seg = detail::make_capsule_segment(a, pose.pos, pose.orn);
    forced_feature(detail::capsule_support_feature(seg.p0, seg.p1, a.radius, -prism.normal), prism, ctx,
                   result);
}

void collide_prism(const cylinder_shape &a, const triangle_prism &prism, const collision_context &ctx,
                   collision_result &result) {
    detail::collide_cylinder_polytope(a, prism.view(), ctx, result);
}

void forced_prism(const cylinder_shape &a, const triangle_prism &prism, const collision_context &ctx,
                  collision_result &result) {
    auto pose = pose_in_prism(ctx);
    auto cyl = detail::place_cylinder(a, pose.pos, pose.orn);
    forced_feature(detail::cylinder_support_feature(cyl, -prism.normal), prism, ctx, result);
}

void collide_prism(const box_shape &a, const triangle_prism &prism, const collision_context &ctx,
                   collision_result &result) {
    detail::box_polytope box(a.half_extents);
    detail::collide_polytopes(box.view(), prism.view(), ctx, result);
}

void forced_prism(const box_shape &a, const triangle_prism &prism, const collision_context &ctx,
                  collision_result &result) {
    detail::box_polytope box(a.half_extents);
    forced_polytope(box.view(), prism, ctx, result);
}

void collide_prism(const polyhedron_shape &a, const triangle_prism &prism, const collision_context &ctx,
                   collision_result &result) {
    detail::collide_polytopes(detail::make_polytope(*a.mesh), prism.view(), ctx, result);
}

void forced_prism(const polyhedron_shape &a, const triangle_prism &prism, const collision_context &ctx,
                  collision_result &result) {
    forced_polytope(detail::make_polytope(*a.mesh), prism, ctx, result);
}

// Shape A against every triangle of the mesh (at posB/ornB in ctx) near it.
template<typename Shape>
void collide_triangles(const Shape &a, const triangle_mesh &mesh, const collision_context &ctx,
                       collision_result &result) {
    auto inv_orn_b = conjugate(ctx.ornB);
    auto local_aabb = shape_aabb(a, rotate(inv_orn_b, ctx.posA - ctx.posB), inv_orn_b * ctx.ornA);
    local_aabb = inset(local_aabb, vector3_one * ctx.threshold);

    collision_result tri_result, exact;
    mesh.visit_triangles(local_aabb, [&](std::size_t t) {
        triangle_prism prism(mesh, t);
        auto prism_ctx = ctx;
        prism_ctx.posB = to_world_space(prism.centroid, ctx.posB, ctx.ornB);

        tri_result.num_points = 0;
        collide_prism(a, prism, prism_ctx, tri_result);
        auto tri = mesh.get_triangle_vertices(t);
        bool forced = false;
        for (std::size_t i = 0; i < tri_result.num_points && !forced; ++i) {
            const auto &p = tri_result.point[i];
            auto w = barycentric_coordinates(p.pivotB + prism.centroid, tri[0], tri[1], tri[2]);
            auto feature = triangle_feature_at(t, w);
            forced = !feature_allows_normal(mesh, t, feature, rotate(inv_orn_b, p.normal));
        }
        exact = tri_result;
        if (forced) {
            tri_result.num_points = 0;
            forced_prism(a, prism, prism_ctx, tri_result);
        }

        auto added = std::size_t(0);
        for (std::size_t i = 0; i < tri_result.num_points; ++i) {
            auto p = tri_result.point[i];
            if (forced) {
                // Along the triangle's normal, each point is A's point over the triangle's
                // plane; points beyond the triangle's edges belong to the neighbours.
                auto on_a = to_object_space(to_world_space(p.pivotA, ctx.posA, ctx.ornA), ctx.posB, ctx.ornB);
                auto normal = mesh.get_triangle_normal(t);
                auto distance = dot(on_a - tri[0], normal);
                if (distance > ctx.threshold || distance < -prism.prism_depth()) continue;
                p.pivotB = on_a - normal * distance;
                p.distance = distance;
                p.normal = rotate(ctx.ornB, normal);
            } else {
                p.pivotB += prism.centroid;
            }
            auto w = barycentric_coordinates(p.pivotB, tri[0], tri[1], tri[2]);
            if (forced && (w.x < -outside_tolerance || w.y < -outside_tolerance || w.z < -outside_tolerance))
                continue;
            p.featureB = triangle_feature_at(t, w);
            result.add_point(p);
            ++added;
        }
        if (!forced || added > 0) return;
        // The shape's supporting feature along the triangle's normal lies beyond the triangle
        // (a round shape on a nearly flat ridge reaches its lowest point over the neighbour):
        // the exact points that are in the triangle stay, with the triangle's normal and their
        // depth along it.
        for (std::size_t i = 0; i < exact.num_points; ++i) {
            auto p = exact.point[i];
            auto on_a = to_object_space(to_world_space(p.pivotA, ctx.posA, ctx.ornA), ctx.posB, ctx.ornB);
            auto on_b = p.pivotB + prism.centroid;
            auto normal = mesh.get_triangle_normal(t);
            auto distance = dot(on_a - on_b, normal);
            auto feature = triangle_feature_at(t, barycentric_coordinates(on_b, tri[0], tri[1], tri[2]));
            if (distance > 0) {
                // A near miss: the neighbours report theirs, but at the mesh's open edge there is
                // none. There the exact point stands as it is, the edge or vertex being active.
                if (!open_beyond(mesh, t, feature) || p.distance > ctx.threshold ||
                    !feature_allows_normal(mesh, t, feature, rotate(inv_orn_b, p.normal)))
                    continue;
                p.pivotB = on_b;
                p.featureB = feature;
                result.add_point(p);
                continue;
            }
            // Where the shape is in the triangle.
            if (distance < -prism.prism_depth()) continue;
            // Across an edge to a coplanar neighbour, the neighbour reports the supporting point.
            if (flat_beyond(mesh, t, feature)) continue;
            p.pivotB = on_a - normal * distance;
            auto w = barycentric_coordinates(p.pivotB, tri[0], tri[1], tri[2]);
            if (w.x < -outside_tolerance || w.y < -outside_tolerance || w.z < -outside_tolerance) continue;
            p.distance = distance;
            p.normal = rotate(ctx.ornB, normal);
            p.featureB = triangle_feature_at(t, w);
            result.add_point(p);
        }
    });
}

} // namespace

namespace detail {

void collide_triangle_mesh(const sphere_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result) {
    collide_triangles(a, b, ctx, result);
}

void collide_triangle_mesh(const capsule_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result) {
    collide_triangles(a, b, ctx, result);
}

void collide_triangle_mesh(const cylinder_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result) {
    collide_triangles(a, b, ctx, result);
}

void collide_triangle_mesh(const box_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result) {
    collide_triangles(a, b, ctx, result);
}

void collide_triangle_mesh(const polyhedron_shape &a, const triangle_mesh &b, const collision_context &ctx,
                           collision_result &result) {
    EDYN_ASSERT(a.mesh);
    collide_triangles(a, b, ctx, result);
}

} // namespace detail

void collide(const sphere_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(b.trimesh);
    detail::collide_triangle_mesh(a, *b.trimesh, ctx, result);
}

void collide(const capsule_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(b.trimesh);
    detail::collide_triangle_mesh(a, *b.trimesh, ctx, result);
}

void collide(const cylinder_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(b.trimesh);
    detail::collide_triangle_mesh(a, *b.trimesh, ctx, result);
}

void collide(const box_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(b.trimesh);
    detail::collide_triangle_mesh(a, *b.trimesh, ctx, result);
}

void collide(const polyhedron_shape &a, const mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    EDYN_ASSERT(b.trimesh);
    detail::collide_triangle_mesh(a, *b.trimesh, ctx, result);
}

namespace {

// Every loaded page near A, each as a mesh, with triangles numbered across pages.
template<typename Shape>
void collide_pages(const Shape &a, const paged_mesh_shape &b, const collision_context &ctx,
                   collision_result &result) {
    EDYN_ASSERT(b.trimesh);
    const auto &paged = *b.trimesh;
    auto inv_orn_b = conjugate(ctx.ornB);
    auto local_aabb = shape_aabb(a, rotate(inv_orn_b, ctx.posA - ctx.posB), inv_orn_b * ctx.ornA);
    local_aabb = inset(local_aabb, vector3_one * ctx.threshold);
    collision_result page_result;
    paged.visit_loaded_pages(local_aabb, [&](std::size_t page, const triangle_mesh &mesh) {
        page_result.num_points = 0;
        detail::collide_triangle_mesh(a, mesh, ctx, page_result);
        for (std::size_t i = 0; i < page_result.num_points; ++i) {
            auto p = page_result.point[i];
            if (p.featureB) p.featureB->part += static_cast<std::int32_t>(paged.first_triangle(page));
            result.add_point(p);
        }
    });
}

} // namespace

void collide(const sphere_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_pages(a, b, ctx, result);
}

void collide(const capsule_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_pages(a, b, ctx, result);
}

void collide(const cylinder_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_pages(a, b, ctx, result);
}

void collide(const box_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_pages(a, b, ctx, result);
}

void collide(const polyhedron_shape &a, const paged_mesh_shape &b, const collision_context &ctx,
             collision_result &result) {
    collide_pages(a, b, ctx, result);
}

void collide(const paged_mesh_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const paged_mesh_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const paged_mesh_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const paged_mesh_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const paged_mesh_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const mesh_shape &a, const sphere_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const mesh_shape &a, const capsule_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const mesh_shape &a, const cylinder_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const mesh_shape &a, const box_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

void collide(const mesh_shape &a, const polyhedron_shape &b, const collision_context &ctx,
             collision_result &result) {
    detail::collide_swapped([](auto &&...args) { collide(args...); }, a, b, ctx, result);
}

} // namespace edyn
