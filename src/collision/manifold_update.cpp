#include "edyn/collision/manifold_update.hpp"
#include "edyn/math/transform.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

namespace {

using id_type = contact_manifold::id_type;
using result_point = collision_result::collision_point;
constexpr auto max_contacts = contact_manifold::max_contacts;

// Frees the point at position `pos` of `ids` by swapping its id with the last live one.
void remove_point_at(contact_manifold &manifold, std::uint32_t pos, contact_point_changes &changes) {
    EDYN_ASSERT(pos < manifold.num_points);
    auto slot = manifold.ids[pos];
    auto last = manifold.num_points - 1;
    manifold.ids[pos] = manifold.ids[last];
    manifold.ids[last] = slot;
    manifold.num_points = last;
    changes.destroyed[changes.num_destroyed++] = slot;
}

// Also places the pivots in world space at `tf`, for the solver.
void assign_geometry(contact_point &cp, const result_point &rp, const manifold_transforms &tf) {
    cp.pivotA = rp.pivotA;
    cp.pivotB = rp.pivotB;
    cp.positionA = to_world_space(rp.pivotA, tf.posA, tf.ornA);
    cp.positionB = to_world_space(rp.pivotB, tf.posB, tf.ornB);
    cp.normal = rp.normal;
    cp.distance = rp.distance;
    cp.featureA = rp.featureA;
    cp.featureB = rp.featureB;
}

// A live point continued by a result point takes its geometry. A held point (one static
// friction holds, contact_anchor_min_lifetime) that touches one body at the same material point
// (its pivot there moved less than contact_reuse_max_distance on that body) keeps its surfaces'
// slip, up to contact_anchor_max_slip: its pivot on the other body moves along the surface to
// where the surfaces stuck. Replaced outright, the pivots of a body that moves more than
// contact_reuse_max_distance or turns more than contact_reuse_max_angle a step held it each
// step only where it then stood: the friction anchor's spring, stretched anew every step to
// carry a steady force, let a box creep off a turning platform. A point that now touches both
// bodies elsewhere (a rolling ball) starts again where it touches, and so does every point of
// a pair that touches at one point: a sphere's pivot stays at the foot of its lever, where the
// normal impulse must act.
void continue_point(contact_point &cp, const result_point &rp, const manifold_transforms &tf,
                    bool one_point) {
    auto slip = cp.positionA - cp.positionB; // The old pivots, refreshed at `tf`.
    const auto same_sqr = contact_reuse_max_distance * contact_reuse_max_distance;
    auto same_on_A = distance_sqr(cp.pivotA, rp.pivotA) <= same_sqr;
    auto same_on_B = distance_sqr(cp.pivotB, rp.pivotB) <= same_sqr;
    assign_geometry(cp, rp, tf);
    if (one_point || cp.lifetime < contact_anchor_min_lifetime || (!same_on_A && !same_on_B)) return;
    slip = project_plane(slip, cp.normal);
    if (length_sqr(slip) > contact_anchor_max_slip * contact_anchor_max_slip) return;
    auto shift = slip - project_plane(cp.positionA - cp.positionB, cp.normal);
    if (same_on_A) {
        cp.positionB -= shift;
        cp.pivotB = to_object_space(cp.positionB, tf.posB, tf.ornB);
    } else {
        cp.positionA += shift;
        cp.pivotA = to_object_space(cp.positionA, tf.posA, tf.ornA);
    }
}

// `ids` stays a permutation of all slots, so the first id past the live ones is a free slot.
void insert_point(contact_manifold &manifold, const result_point &rp, const manifold_transforms &tf,
                  contact_point_changes &changes) {
    EDYN_ASSERT(manifold.num_points < max_contacts);
    auto slot = manifold.ids[manifold.num_points++];
    auto &cp = manifold.point[slot];
    cp = contact_point{};
    assign_geometry(cp, rp, tf);
    changes.created[changes.num_created++] = slot;
}

void refresh_points(contact_manifold &manifold, const manifold_transforms &tf,
                    contact_point_changes &changes) {
    const auto drift_sqr = contact_drift_threshold * contact_drift_threshold;

    for (std::uint32_t pos = 0; pos < manifold.num_points;) {
        auto &cp = manifold.point[manifold.ids[pos]];
        ++cp.lifetime;
        cp.positionA = to_world_space(cp.pivotA, tf.posA, tf.ornA);
        cp.positionB = to_world_space(cp.pivotB, tf.posB, tf.ornB);
        auto d = cp.positionA - cp.positionB;
        cp.distance = dot(d, cp.normal);
        auto tangential = d - cp.normal * cp.distance;

        if (cp.distance > manifold.separation_threshold || length_sqr(tangential) > drift_sqr) {
            // The last live point moved into `pos` and has not been visited yet.
            remove_point_at(manifold, pos, changes);
        } else {
            ++pos;
        }
    }
}

// Features can decide a match when each side has one in both points or in neither, and at
// least one side has them.
bool features_comparable(const contact_point &cp, const result_point &rp) {
    auto hasA = cp.featureA.has_value();
    auto hasB = cp.featureB.has_value();
    return hasA == rp.featureA.has_value() && hasB == rp.featureB.has_value() && (hasA || hasB);
}

bool features_equal(const contact_point &cp, const result_point &rp) {
    return (!cp.featureA || *cp.featureA == *rp.featureA) && (!cp.featureB || *cp.featureB == *rp.featureB);
}

// Position in `ids` of the live, not yet matched point that `rp` continues, or -1.
int find_match(const contact_manifold &manifold, const std::array<bool, max_contacts> &matched,
               const result_point &rp) {
    const auto caching_sqr = contact_caching_threshold * contact_caching_threshold;
    int best_pos = -1;
    int best_rank = 3;
    auto best_dist = large_scalar;

    for (std::uint32_t pos = 0; pos < manifold.num_points; ++pos) {
        auto slot = manifold.ids[pos];
        if (matched[slot]) continue;
        auto &cp = manifold.point[slot];
        auto dist = std::min(distance_sqr(cp.pivotA, rp.pivotA), distance_sqr(cp.pivotB, rp.pivotB));
        int rank;

        // Equal features win, then nearness: a clipped point may change its feature label
        // (vertex, edge) from one step to the next while staying where it was, and it must keep
        // its impulses for warm starting to work.
        auto same_features = features_comparable(cp, rp) && features_equal(cp, rp);
        auto near = dist <= caching_sqr;
        if (same_features) {
            rank = near ? 0 : 2;
        } else {
            if (!near) continue;
            rank = 1;
        }

        if (rank < best_rank || (rank == best_rank && dist < best_dist)) {
            best_pos = static_cast<int>(pos);
            best_rank = rank;
            best_dist = dist;
        }
    }

    return best_pos;
}

// Twice the area of the quadrilateral p, squared: the largest cross product of the three ways
// of pairing the points into diagonals, which is the area of the convex quadrilateral when the
// points form one.
scalar quad_area_sqr(const vector3 &p0, const vector3 &p1, const vector3 &p2, const vector3 &p3) {
    auto a = length_sqr(cross(p0 - p1, p2 - p3));
    auto b = length_sqr(cross(p0 - p2, p1 - p3));
    auto c = length_sqr(cross(p0 - p3, p1 - p2));
    return std::max(a, std::max(b, c));
}

struct candidate {
    vector3 position; // pivot on A
    scalar distance;
    int slot;         // >= 0 for live points
    int result_index; // >= 0 for new points
};

// Chooses which max_contacts of the candidates to keep: the deepest, plus the three others that
// span the largest area with it. Candidates come live points first, so ties keep them.
std::array<bool, 2 * max_contacts> select_points(const candidate *cands, std::size_t count) {
    EDYN_ASSERT(count > max_contacts && count <= 2 * max_contacts);
    std::size_t deepest = 0;
    for (std::size_t i = 1; i < count; ++i) {
        if (cands[i].distance < cands[deepest].distance) deepest = i;
    }

    std::array<std::size_t, 2 * max_contacts> others{};
    std::size_t num_others = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (i != deepest) others[num_others++] = i;
    }

    std::array<std::size_t, 3> best{others[0], others[1], others[2]};
    auto best_area = scalar(-1);
    auto &p = cands[deepest].position;

    for (std::size_t i = 0; i < num_others; ++i) {
        for (std::size_t j = i + 1; j < num_others; ++j) {
            for (std::size_t k = j + 1; k < num_others; ++k) {
                auto area = quad_area_sqr(p, cands[others[i]].position, cands[others[j]].position,
                                          cands[others[k]].position);
                if (area > best_area) {
                    best_area = area;
                    best = {others[i], others[j], others[k]};
                }
            }
        }
    }

    std::array<bool, 2 * max_contacts> keep{};
    keep[deepest] = true;
    for (auto idx : best)
        keep[idx] = true;
    return keep;
}

void insert_new_points(contact_manifold &manifold, const collision_result &result, const int *pending,
                       std::size_t num_pending, const manifold_transforms &tf,
                       contact_point_changes &changes) {
    if (manifold.num_points + num_pending <= max_contacts) {
        for (std::size_t i = 0; i < num_pending; ++i)
            insert_point(manifold, result.point[pending[i]], tf, changes);
        return;
    }

    std::array<candidate, 2 * max_contacts> cands;
    std::size_t count = 0;
    for (std::uint32_t pos = 0; pos < manifold.num_points; ++pos) {
        auto slot = manifold.ids[pos];
        auto &cp = manifold.point[slot];
        cands[count++] = {cp.pivotA, cp.distance, slot, -1};
    }
    for (std::size_t i = 0; i < num_pending; ++i) {
        auto &rp = result.point[pending[i]];
        cands[count++] = {rp.pivotA, rp.distance, -1, pending[i]};
    }

    auto keep = select_points(cands.data(), count);

    // Removals first: they free the slots that the new points take.
    for (std::size_t i = 0; i < count; ++i) {
        if (keep[i] || cands[i].slot < 0) continue;
        auto it = std::find(manifold.ids.begin(), manifold.ids.begin() + manifold.num_points,
                            static_cast<id_type>(cands[i].slot));
        remove_point_at(manifold, static_cast<std::uint32_t>(it - manifold.ids.begin()), changes);
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (keep[i] && cands[i].result_index >= 0)
            insert_point(manifold, result.point[cands[i].result_index], tf, changes);
    }
}

} // namespace

contact_point_changes refresh_contact_manifold(contact_manifold &manifold, const manifold_transforms &tf) {
    EDYN_ASSERT(manifold.num_points <= max_contacts);
    contact_point_changes changes;
    changes.num_points_before = manifold.num_points;
    refresh_points(manifold, tf, changes);
    changes.num_points_after = manifold.num_points;
    return changes;
}

contact_point_changes update_contact_manifold(contact_manifold &manifold, const manifold_transforms &tf,
                                              const collision_result &result, bool shapes_changed,
                                              bool one_point) {
    EDYN_ASSERT(manifold.num_points <= max_contacts);
    EDYN_ASSERT(result.num_points <= max_contacts);
    contact_point_changes changes;
    changes.num_points_before = manifold.num_points;
    refresh_points(manifold, tf, changes);

    std::array<bool, max_contacts> matched{};
    std::array<int, max_contacts> pending{};
    std::size_t num_pending = 0;

    for (std::size_t r = 0; r < result.num_points; ++r) {
        auto &rp = result.point[r];
        // A pair that touches at one point has one place of contact: the live point is it.
        auto pos = !one_point                                             ? find_match(manifold, matched, rp)
                   : manifold.num_points > 0 && !matched[manifold.ids[0]] ? 0
                                                                          : -1;
        if (pos >= 0) {
            auto slot = manifold.ids[static_cast<std::size_t>(pos)];
            continue_point(manifold.point[slot], rp, tf, one_point);
            matched[slot] = true;
        } else if (rp.distance <= manifold.separation_threshold) {
            pending[num_pending++] = static_cast<int>(r);
        }
    }

    // A continued point that is now too far apart ends here, and so does one that lies on a shape
    // that has changed or that the result of a one-point pair did not continue.
    for (std::uint32_t pos = 0; pos < manifold.num_points;) {
        auto slot = manifold.ids[pos];
        if ((matched[slot] && manifold.point[slot].distance > manifold.separation_threshold) ||
            ((shapes_changed || one_point) && !matched[slot])) {
            remove_point_at(manifold, pos, changes);
        } else {
            ++pos;
        }
    }

    insert_new_points(manifold, result, pending.data(), num_pending, tf, changes);
    changes.num_points_after = manifold.num_points;
    return changes;
}

contact_point_changes clear_contact_manifold(contact_manifold &manifold) {
    contact_point_changes changes;
    changes.num_points_before = manifold.num_points;
    while (manifold.num_points > 0)
        remove_point_at(manifold, manifold.num_points - 1, changes);
    return changes;
}

bool can_reuse_contacts(const contact_manifold &manifold, const manifold_transforms &tf, scalar approach,
                        const shape_epoch_pair &shape_epochs) noexcept {
    auto &last = manifold.last_collide;
    if (!last.valid || last.shape_epochs != shape_epochs || approach > contact_reuse_max_distance)
        return false;
    const auto max_dist_sqr = contact_reuse_max_distance * contact_reuse_max_distance;
    if (distance_sqr(tf.posA, last.posA) > max_dist_sqr || distance_sqr(tf.posB, last.posB) > max_dist_sqr) {
        return false;
    }
    // Two unit quaternions differ by a rotation of angle a where |dot| = cos(a / 2).
    static const auto min_cos = std::cos(contact_reuse_max_angle / 2);
    return std::abs(dot(tf.ornA, last.ornA)) >= min_cos && std::abs(dot(tf.ornB, last.ornB)) >= min_cos;
}

void remember_collide(contact_manifold &manifold, const manifold_transforms &tf,
                      const shape_epoch_pair &shape_epochs) noexcept {
    manifold.last_collide = {tf.posA, tf.posB, tf.ornA, tf.ornB, shape_epochs, true};
}

} // namespace edyn
