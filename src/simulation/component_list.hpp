#ifndef EDYN_SRC_SIMULATION_COMPONENT_LIST_HPP
#define EDYN_SRC_SIMULATION_COMPONENT_LIST_HPP

#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/shape_index.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/shapes/shapes.hpp"

namespace edyn {

// A list of component types, carried as template arguments only (it holds nothing): the lists
// of edyn's components that the registry's listeners connect and clear, and that the
// asynchronous mode replicates.
template<typename... Components>
struct component_list {};

// Changes that must wake a sleeping body (besides its transform): in the registry that steps,
// and, in asynchronous mode, at once in the main registry, which shows the body awake.
using waking_components = component_list<linvel, angvel, gravity, mass, inertia, material, shape_index,
                                         plane_shape, sphere_shape, cylinder_shape, capsule_shape, box_shape,
                                         polyhedron_shape, compound_shape, mesh_shape, paged_mesh_shape>;

// Components whose arrival or removal wakes a body: its own gravity, and sleeping_disabled_tag
// (a body that may not sleep is awake). A material's is handled with the sensor_tag it decides.
using waking_presence_components = component_list<gravity, sleeping_disabled_tag>;

} // namespace edyn

#endif // EDYN_SRC_SIMULATION_COMPONENT_LIST_HPP
