#ifndef EDYN_COLLISION_SHAPE_EPOCH_HPP
#define EDYN_COLLISION_SHAPE_EPOCH_HPP

#include <array>
#include <cstdint>

namespace edyn {

/// Counts how many times a body's shape has been replaced or patched (none: zero).
///
/// Kept by the engine on bodies whose shape changed. A manifold remembers the counts of its two
/// bodies when collide() runs for it, so that a change to one body's shape stops the reuse of
/// that body's contact points only (see can_reuse_contacts).
struct shape_epoch {
    std::uint32_t value{0}; ///< Number of shape changes so far; 0 by default.
};

/// The shape epochs of a manifold's two bodies, in the manifold's body order.
using shape_epoch_pair = std::array<std::uint32_t, 2>;

} // namespace edyn

#endif // EDYN_COLLISION_SHAPE_EPOCH_HPP
