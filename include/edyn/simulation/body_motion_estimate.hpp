#ifndef EDYN_SIMULATION_BODY_MOTION_ESTIMATE_HPP
#define EDYN_SIMULATION_BODY_MOTION_ESTIMATE_HPP

#include "edyn/collision/broadphase.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/settings.hpp"

namespace edyn {

/// How far a dynamic body may go in the coming step, for its broadphase proxy: its linear
/// velocity times the step, and how far a turn at its spin for a step can move a side of its
/// AABB out: the angle times the farthest the shape reaches from the centre of mass (the smaller
/// of its bounding sphere's and its AABB's bounds), and never past that reach (a spinning sphere
/// reaches nowhere new). Gravity's share of the step, g dt² (2.7 mm at 60 Hz), is left to the
/// broadphase margin.
/// @param settings The world's settings (fixed_dt).
/// @param registry The registry holding the body.
/// @param e The body.
/// @param aabb Its current AABB.
/// @param estimate Set to the body's expected displacement and reach.
/// @return False for bodies that are not dynamic (a kinematic body may be moved by setting its
///         position) or whose velocities are not finite: those are left to the broadphase.
bool estimate_body_motion(const settings &settings, const registry &registry, entity e, const AABB &aabb,
                          proxy_motion_estimate &estimate);

/// estimate_body_motion bound to `settings`, which must outlive the returned estimator.
/// @param settings The world's settings.
inline motion_estimator body_motion_estimator(const settings &settings) {
    return motion_estimator{connect_arg<&estimate_body_motion>, settings};
}

} // namespace edyn

#endif // EDYN_SIMULATION_BODY_MOTION_ESTIMATE_HPP
