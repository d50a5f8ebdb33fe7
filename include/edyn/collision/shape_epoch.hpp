#ifndef EDYN_COLLISION_SHAPE_EPOCH_HPP
#define EDYN_COLLISION_SHAPE_EPOCH_HPP

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
struct shape_epoch_pair {
    std::uint32_t a{0}; ///< Shape epoch of the manifold's first body.
    std::uint32_t b{0}; ///< Shape epoch of the manifold's second body.
    /// Equal when both epochs are (two integer comparisons: checked for every manifold, every
    /// step).
    bool operator==(const shape_epoch_pair &) const noexcept = default;
};

} // namespace edyn

#endif // EDYN_COLLISION_SHAPE_EPOCH_HPP
