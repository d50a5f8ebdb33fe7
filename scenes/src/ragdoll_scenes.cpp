#include "edyn_scenes/scenes.hpp"
#include <algorithm>

namespace edyn::scenes {

std::vector<ragdoll_entities> make_ragdoll_pile(registry &registry, unsigned count, unsigned columns,
                                                scalar height, const vector3 &origin) {
    // Far enough apart that no two overlap when made, whichever way they face: the arms of a
    // 1.8 m rag doll span a little over 2 m, and leaning moves them.
    const scalar spacing = scalar(2.8), layer_height = scalar(2.2);
    columns = std::max(columns, 1u);
    const unsigned per_layer = columns * columns;
    std::vector<ragdoll_entities> ragdolls;
    ragdolls.reserve(count);
    for (unsigned i = 0; i < count; ++i) {
        auto layer = i / per_layer, row = (i % per_layer) / columns, column = i % columns;
        ragdoll_simple_def def;
        def.friction = scalar(0.6);
        auto centre = (scalar(columns) - 1) / 2;
        def.position =
            origin + vector3{(scalar(column) - centre) * spacing, height + scalar(layer) * layer_height,
                             (scalar(row) - centre) * spacing};
        // Each layer turned a quarter turn from the one below, so that they fall across each
        // other, and each rag doll leaning a little its own way so that it topples.
        auto yaw = quaternion_axis_angle(vector3_y, scalar(layer % 2) * pi / 2 + scalar(i) * scalar(0.4));
        auto lean = quaternion_axis_angle(normalize(vector3{scalar(i % 3) - 1, 0, 1}), to_radians(12));
        def.orientation = normalize(lean * yaw);
        ragdolls.push_back(make_ragdoll(registry, def));
    }
    return ragdolls;
}

} // namespace edyn::scenes
