#include "edyn/collision/collision_result.hpp"
#include "edyn/collision/detail/collide_common.hpp"
#include <algorithm>
#include <utility>

namespace edyn {

namespace {

bool same_contact(const collision_result::collision_point &a,
                  const collision_result::collision_point &b) noexcept {
    constexpr auto merge_sqr = detail::contact_merge_distance * detail::contact_merge_distance;
    return distance_sqr(a.pivotA, b.pivotA) <= merge_sqr || distance_sqr(a.pivotB, b.pivotB) <= merge_sqr;
}

// Monotonic measure of the area spanned by four points: four times the squared area of the
// largest quadrilateral through them (half the cross product of its diagonals), without the root.
scalar area_measure(const vector3 &p0, const vector3 &p1, const vector3 &p2, const vector3 &p3) noexcept {
    auto a0 = length_sqr(cross(p2 - p0, p3 - p1));
    auto a1 = length_sqr(cross(p3 - p0, p1 - p2));
    auto a2 = length_sqr(cross(p1 - p0, p2 - p3));
    return std::max(a0, std::max(a1, a2));
}

// Area measure of the four points (pivots on A: every point of one manifold is expressed in A's
// space) with point `skip` replaced by `p`.
scalar area_with(const std::array<collision_result::collision_point, collision_result::max_contacts> &points,
                 std::size_t skip, const vector3 &p) noexcept {
    vector3 v[4];
    for (std::size_t i = 0; i < 4; ++i) {
        v[i] = i == skip ? p : points[i].pivotA;
    }
    return area_measure(v[0], v[1], v[2], v[3]);
}

} // namespace

void collision_result::add_point(const collision_point &p) {
    for (std::size_t i = 0; i < num_points; ++i) {
        if (same_contact(point[i], p)) {
            if (p.distance < point[i].distance) point[i] = p;
            return;
        }
    }

    if (num_points < max_contacts) {
        point[num_points++] = p;
        return;
    }

    static_assert(max_contacts == 4, "the reduction below spans quadrilaterals");
    std::size_t deepest = 0;
    for (std::size_t i = 1; i < max_contacts; ++i) {
        if (point[i].distance < point[deepest].distance) deepest = i;
    }
    auto new_is_deepest = p.distance < point[deepest].distance;

    // The new point replaces the point whose removal leaves the largest area, provided that
    // beats the current area; the deepest point of all five is never the one dropped.
    auto best_area = new_is_deepest
                         ? scalar(-1)
                         : area_measure(point[0].pivotA, point[1].pivotA, point[2].pivotA, point[3].pivotA);
    auto replace = max_contacts;
    for (std::size_t i = 0; i < max_contacts; ++i) {
        if (!new_is_deepest && i == deepest) continue;
        auto area = area_with(point, i, p.pivotA);
        if (area > best_area) {
            best_area = area;
            replace = i;
        }
    }
    if (replace < max_contacts) {
        point[replace] = p;
    }
}

void collision_result::swap() {
    for (std::size_t i = 0; i < num_points; ++i) {
        auto &p = point[i];
        std::swap(p.pivotA, p.pivotB);
        std::swap(p.featureA, p.featureB);
        p.normal = -p.normal;
    }
}

} // namespace edyn
