#ifndef EDYN_EDYN_HPP
#define EDYN_EDYN_HPP

/// @file
/// @brief The whole public API, layer by layer (see DESIGN.md): include this one header to use
/// edyn.
#include "edyn/config/assert.hpp"
#include "edyn/config/version.hpp"

#include "edyn/ecs/ecs.hpp"

#include "edyn/math/math.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/math/scalar.hpp"
#include "edyn/math/transform.hpp"
#include "edyn/math/vector2.hpp"
#include "edyn/math/vector3.hpp"

#include "edyn/parallel/background_tasks.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include "edyn/parallel/task_scheduler.hpp"

#include "edyn/shapes/aabb.hpp"
#include "edyn/shapes/convex_hull.hpp"
#include "edyn/shapes/moment_of_inertia.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/shapes/shapes.hpp"
#include "edyn/shapes/validate_shape.hpp"

#include "edyn/collision/broadphase.hpp"
#include "edyn/collision/collide.hpp"
#include "edyn/collision/collision_filter.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/collision/shape_epoch.hpp"
#include "edyn/collision/shape_raycast.hpp"
#include "edyn/collision/should_collide.hpp"

#include "edyn/dynamics/body_limits.hpp"
#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/rigidbody_def.hpp"
#include "edyn/dynamics/shape_index.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"

#include "edyn/constraints/constraint_links.hpp"
#include "edyn/constraints/constraint_solver.hpp"
#include "edyn/constraints/constraints.hpp"
#include "edyn/constraints/external_entity.hpp"
#include "edyn/constraints/make_constraint.hpp"

#include "edyn/simulation/contact_events.hpp"
#include "edyn/simulation/discontinuity.hpp"
#include "edyn/simulation/execution_mode.hpp"
#include "edyn/simulation/island.hpp"
#include "edyn/simulation/raycast.hpp"
#include "edyn/simulation/raycast_async.hpp"
#include "edyn/simulation/replication.hpp"
#include "edyn/simulation/settings.hpp"
#include "edyn/simulation/world.hpp"

#include "edyn/networking/action_list.hpp"
#include "edyn/networking/asset_ref.hpp"
#include "edyn/networking/client.hpp"
#include "edyn/networking/networked_components.hpp"
#include "edyn/networking/networked_tag.hpp"
#include "edyn/networking/packet/edyn_packet.hpp"
#include "edyn/networking/remote_client.hpp"
#include "edyn/networking/server.hpp"
#include "edyn/networking/simulated_link.hpp"
#include "edyn/serialization/math_types.hpp"
#include "edyn/serialization/memory_archive.hpp"
#include "edyn/serialization/std_types.hpp"
#include "edyn/util/load_mesh_from_obj.hpp"
#include "edyn/util/ragdoll.hpp"

#endif // EDYN_EDYN_HPP
