#ifndef EDYN_SRC_SIMULATION_COMPONENT_LIST_HPP
#define EDYN_SRC_SIMULATION_COMPONENT_LIST_HPP

#include "edyn/dynamics/mass.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/dynamics/shape_index.hpp"
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

} // namespace edyn

#endif // EDYN_SRC_SIMULATION_COMPONENT_LIST_HPP
