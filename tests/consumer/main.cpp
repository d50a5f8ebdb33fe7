// Uses the installed package the way an application would: registry plus math.
#include <cstdio>
#include <edyn/edyn.hpp>

int main() {
    edyn::registry registry;
    auto entity = registry.create();
    registry.emplace<edyn::vector3>(entity, edyn::vector3{1, 2, 3});
    auto q = edyn::quaternion_axis_angle(edyn::vector3_y, edyn::to_radians(90));
    auto v = edyn::rotate(q, registry.get<edyn::vector3>(entity));
    std::printf("%.3f %.3f %.3f\n", double(v.x), double(v.y), double(v.z));
    return registry.valid(entity) ? 0 : 1;
}
