#ifndef EDYN_COLLISION_COLLISION_FEATURE_HPP
#define EDYN_COLLISION_COLLISION_FEATURE_HPP

#include <cstdint>
#include <variant>

namespace edyn {

enum class box_feature : std::uint8_t { vertex, edge, face };
enum class cylinder_feature : std::uint8_t { face, cap_edge, side_edge };
enum class capsule_feature : std::uint8_t { hemisphere, side };
enum class triangle_feature : std::uint8_t { vertex, edge, face };
enum class polyhedron_feature : std::uint8_t { vertex, edge, face };

// The closest feature of a shape in a collision point, e.g. {box_feature::face, 2} for a box's
// upper face. Index meanings are documented next to each shape.
struct collision_feature {
    std::variant<std::monostate, box_feature, cylinder_feature, capsule_feature, triangle_feature,
                 polyhedron_feature>
        feature;
    std::uint32_t index{0};
    // Child shape of a compound, or triangle of a mesh, the feature belongs to; -1 when none.
    std::int32_t part{-1};

    bool operator==(const collision_feature &) const = default;
};

} // namespace edyn

#endif // EDYN_COLLISION_COLLISION_FEATURE_HPP
