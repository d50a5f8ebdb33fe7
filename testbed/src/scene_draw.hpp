// Turns the bodies of a registry into the renderer's instances: each shape as unit meshes
// placed at the body's present transform (a capsule as a cylinder and two spheres, a compound as
// its children), polyhedra into the CPU batch, triangle meshes and planes as they are.
#ifndef EDYN_TESTBED_SCENE_DRAW_HPP
#define EDYN_TESTBED_SCENE_DRAW_HPP

#include "renderer.hpp"
#include <edyn/edyn.hpp>

namespace testbed {

void draw_bodies(const edyn::registry &registry, renderer &r, bool grey_sleeping);

} // namespace testbed

#endif // EDYN_TESTBED_SCENE_DRAW_HPP
