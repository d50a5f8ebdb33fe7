// Closest points between two shapes without a registry: collide() for each pair of shapes.
// A box hovering 0.1 m above another, then tilted onto an edge: the distances are checked
// against the geometry and the closest features are named.
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

const char *name(const std::optional<edyn::collision_feature> &feature) {
    if (!feature) return "none";
    if (auto *box = std::get_if<edyn::box_feature>(&feature->feature)) {
        switch (*box) {
        case edyn::box_feature::vertex:
            return "vertex";
        case edyn::box_feature::edge:
            return "edge";
        case edyn::box_feature::face:
            return "face";
        }
    }
    return "other";
}

} // namespace

int main() {
    bool ok = true;

    // As in the manual: two unit boxes, B above A, here with a 0.1 m gap.
    auto box = edyn::box_shape{edyn::vector3{0.5, 0.5, 0.5}};
    auto ctx = edyn::collision_context{};
    ctx.posA = edyn::vector3{0, 0, 0};
    ctx.ornA = edyn::quaternion_identity;
    ctx.posB = edyn::vector3{0, 2 * box.half_extents.y + 0.1f, 0};
    ctx.ornB = edyn::quaternion_identity;
    // Shapes farther apart than the threshold give no points.
    ctx.threshold = 0.2;
    auto result = edyn::collision_result{};
    edyn::collide(box, box, ctx, result);
    if (result.num_points == 0) {
        std::printf("no closest points found for boxes 0.1 m apart\n");
        return 1;
    }
    // Face against face: four points, each 0.1 m apart, one per corner of B's lower face. Each
    // point names its own features: A's upper face (face 2), and a corner of B on its lower face
    // (a vertex whose index has bit 2 set: -y).
    auto &point = result.point[0];
    auto featureA = std::get<edyn::box_feature>(point.featureA->feature);
    auto upper_face = featureA == edyn::box_feature::face && point.featureA->index == 2;
    std::printf("stacked: %zu points, distance %.3f m (expected 4 points, 0.100), normal (%.0f, %.0f, %.0f), "
                "A's %s %u and B's %s %u (expected A's face 2 and one of B's vertices 2, 3, 6, 7)\n",
                result.num_points, point.distance, point.normal.x, point.normal.y, point.normal.z,
                name(point.featureA), point.featureA->index, name(point.featureB), point.featureB->index);
    auto lower_corner = point.featureB &&
                        std::get<edyn::box_feature>(point.featureB->feature) == edyn::box_feature::vertex &&
                        (point.featureB->index & 2) != 0;
    ok = result.num_points == 4 && std::abs(point.distance - 0.1f) < 1e-4f && upper_face && lower_corner &&
         point.normal.y < -0.999f;

    // B turned 45 degrees about z: its lowest edge, 0.5 sqrt(2) below its centre, is closest,
    // reported as two points at its ends (B's vertices) over A's face.
    ctx.ornB = edyn::quaternion_axis_angle({0, 0, 1}, edyn::to_radians(45));
    ctx.posB = edyn::vector3{0, 1.3, 0};
    result = edyn::collision_result{};
    edyn::collide(box, box, ctx, result);
    auto expected = 1.3f - 0.5f - 0.5f * std::sqrt(2.0f);
    if (result.num_points == 0) {
        std::printf("no closest points found for the tilted box\n");
        return 1;
    }
    auto &edge_point = result.point[0];
    std::printf("tilted:  %zu points, distance %.4f m (expected 1.3 - 0.5 - 0.5 sqrt(2) = %.4f), B's "
                "feature: %s (expected 2 points, vertex)\n",
                result.num_points, edge_point.distance, expected, name(edge_point.featureB));
    ok = ok && result.num_points == 2 && std::abs(edge_point.distance - expected) < 1e-4f &&
         edge_point.featureB &&
         std::get<edyn::box_feature>(edge_point.featureB->feature) == edyn::box_feature::vertex;

    // Any pair of shapes: a sphere 0.3 m from the box's corner, along its diagonal.
    auto sphere = edyn::sphere_shape{0.25};
    auto corner = edyn::vector3{0.5, 0.5, 0.5};
    auto direction = edyn::normalize(corner);
    ctx = edyn::collision_context{};
    ctx.posA = corner + direction * (0.25f + 0.1f);
    ctx.posB = edyn::vector3_zero;
    ctx.threshold = 0.2;
    result = edyn::collision_result{};
    edyn::collide(sphere, box, ctx, result);
    auto corner_distance = result.num_points > 0 ? result.point[0].distance : -1;
    std::printf("sphere:  %zu point, distance %.4f m (expected 0.1000), box feature %s (expected vertex)\n",
                result.num_points, corner_distance,
                result.num_points > 0 ? name(result.point[0].featureB) : "none");
    ok = ok && result.num_points == 1 && std::abs(corner_distance - 0.1f) < 1e-4f &&
         result.point[0].featureB &&
         std::get<edyn::box_feature>(result.point[0].featureB->feature) == edyn::box_feature::vertex;

    return ok ? 0 : 1;
}
