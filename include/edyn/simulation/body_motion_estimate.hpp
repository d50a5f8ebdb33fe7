#ifndef EDYN_SIMULATION_BODY_MOTION_ESTIMATE_HPP
#define EDYN_SIMULATION_BODY_MOTION_ESTIMATE_HPP

#include "edyn/collision/broadphase.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/settings.hpp"

namespace edyn {

/// How far dynamic bodies may go in the coming step, for their broadphase proxies: the linear
/// velocity times the step, and how far a turn at the body's spin for a step can move a side of
/// its AABB out: the angle times the farthest the shape reaches from the centre of mass
/// (shape_reach), and never past that reach (a spinning sphere reaches nowhere new). Gravity's
/// share of the step, g dt² (2.7 mm at 60 Hz), is left to the broadphase margin.
///
/// The component pools are looked up once, when it is made, not once per body; it reads the
/// registry it was made from and is valid while that registry's pools are (the step makes one
/// for each broadphase update).
class body_motion_estimate {
public:
    /// @param settings The world's settings (fixed_dt); must outlive this object.
    /// @param registry The registry holding the bodies.
    body_motion_estimate(const settings &settings, const registry &registry);

    /// Estimates the motion of one body.
    /// @param registry The registry this object was made from (the shape is looked up in it).
    /// @param e The body.
    /// @param aabb Its current AABB.
    /// @param estimate Set to the body's expected displacement and reach.
    /// @return False for bodies that are not dynamic (a kinematic body may be moved by setting its
    ///         position) or whose velocities are not finite: those are left to the broadphase.
    bool operator()(const registry &registry, entity e, const AABB &aabb,
                    proxy_motion_estimate &estimate) const;

    /// This object as the broadphase takes it; it must outlive the returned estimator.
    motion_estimator estimator() const {
        return motion_estimator{connect_arg<&body_motion_estimate::operator()>, *this};
    }

private:
    scalar dt;
    const edyn::storage<dynamic_tag> *dynamic;
    const edyn::storage<linvel> *linear;
    const edyn::storage<angvel> *angular;
    const edyn::storage<position> *centres;
    const edyn::storage<center_of_mass> *offsets;
};

/// One body's estimate, as body_motion_estimate gives it, for a single call.
/// @param settings The world's settings (fixed_dt).
/// @param registry The registry holding the body.
/// @param e The body.
/// @param aabb Its current AABB.
/// @param estimate Set to the body's expected displacement and reach.
/// @return As body_motion_estimate::operator().
bool estimate_body_motion(const settings &settings, const registry &registry, entity e, const AABB &aabb,
                          proxy_motion_estimate &estimate);

} // namespace edyn

#endif // EDYN_SIMULATION_BODY_MOTION_ESTIMATE_HPP
