#ifndef EDYN_SCENES_SCENES_HPP
#define EDYN_SCENES_SCENES_HPP

#include <array>
#include <cstdint>
#include <edyn/edyn.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace edyn::scenes {

// A static ground: a plane through the origin with normal +y.
entity make_ground(registry &registry, scalar friction = scalar(0.6), scalar restitution = 0);

// Triangle meshes. A grid of `cells` x `cells` squares of side `cell_size` in the xz plane,
// centred on the origin, two triangles per square facing +y, heights from height(x, z).
std::shared_ptr<triangle_mesh> make_grid_mesh(unsigned cells, scalar cell_size,
                                              const std::function<scalar(scalar, scalar)> &height);

// A flat floor at y = 0 tessellated into `cells` x `cells` squares (two triangles each), as a
// static body with a mesh_shape.
entity make_mesh_floor(registry &registry, unsigned cells, scalar cell_size, scalar friction = scalar(0.6),
                       scalar restitution = 0);

// Rolling terrain: a height grid of `cells` x `cells` squares of `cell_size`, hills up to
// `amplitude` high made of a few sine waves, as a static body with a mesh_shape. terrain_height
// gives the surface's height of the same function (exact at the grid's vertices).
scalar terrain_height(scalar x, scalar z, scalar amplitude);
entity make_terrain(registry &registry, unsigned cells, scalar cell_size, scalar amplitude,
                    scalar friction = scalar(0.6));

// The terrain of make_mesh_pile: a make_terrain grid of `cells` x `cells` squares of
// `cell_size` (100 x 100 of 1.25 m: 20,000 triangles over 125 m by 125 m), hills up to
// `amplitude`.
struct mesh_pile_terrain {
    unsigned cells{100};
    scalar cell_size{scalar(1.25)};
    scalar amplitude{3};
    scalar friction{scalar(0.6)};
    // Where the terrain's body (and the pile with it) is placed.
    vector3 origin{vector3_zero};
    // A paged_mesh_shape of pages of at most page_size triangles instead of a mesh_shape.
    bool paged{false};
    std::size_t page_size{2000};
};

// The height of that terrain's triangles at (x, z) (world space): terrain_height at the
// vertices, linear across each triangle in between. None outside the grid.
std::optional<scalar> terrain_surface_height(const mesh_pile_terrain &terrain, scalar x, scalar z);

// `count` convex bodies of 1 kg and friction 0.6 dropped on a mesh terrain: boxes, spheres,
// capsules and convex polyhedra (irregular rocks) in equal share, their largest dimension 0.5 to
// 1, in a grid `width` bodies wide and 2.2 m apart centred on the origin, layer after layer, each
// body `height` above the terrain under it and each layer 3.3 m above the one below. Sizes and
// orientations come from a fixed-seed generator. The rocks are built with their centroid at the
// origin and their principal axes along the object axes (no centre of mass offset, diagonal
// inertia). No ground plane: whatever leaves the terrain falls for ever.
struct mesh_pile_scene {
    entity terrain{null};
    std::vector<entity> bodies;
};
mesh_pile_scene make_mesh_pile(registry &registry, unsigned count, unsigned width = 30, scalar height = 2,
                               const mesh_pile_terrain &terrain = {}, std::uint32_t seed = 1);

// Pyramid of unit boxes (half extent `half_extent`) standing on the ground, `base` boxes wide
// in its bottom row and one box fewer in each row above: base * (base + 1) / 2 boxes. Returns
// the boxes from the bottom row up; the last one is the top box.
std::vector<entity> make_pyramid(registry &registry, unsigned base, scalar half_extent = scalar(0.5),
                                 const vector3 &origin = vector3_zero);

// A vertical tower of `count` boxes, one on top of the other. Returns them bottom up.
std::vector<entity> make_tower(registry &registry, unsigned count, scalar half_extent = scalar(0.5),
                               const vector3 &origin = vector3_zero);

// Stacks the solver's contact constants were not tuned on (they were tuned with the tower and
// the pyramids above); each stands on its own when built, with no ground but where stated.

// A tower of `count` boxes on the ground, one on top of the other, of different widths,
// depths, heights and masses (0.5 to 10 kg, up to 8 times their neighbours'): the sizes go
// round a fixed table, so that heavy boxes stand on light ones and wide ones on narrow ones.
// Returns them bottom up.
std::vector<entity> make_mixed_tower(registry &registry, unsigned count = 15,
                                     const vector3 &origin = vector3_zero);

// A wall of bricks in running bond standing on the ground along x, centred on `origin`: `rows`
// rows of `bricks_per_row` bricks of half extents `brick_half_extents` and 2 kg, every other
// row shifted by half a brick and closed at each end by a half brick (1 kg), so that the ends
// are flush. Returns the bricks row by row from the bottom, each row along +x.
std::vector<entity> make_brick_wall(registry &registry, unsigned rows, unsigned bricks_per_row,
                                    const vector3 &brick_half_extents = {scalar(0.25), scalar(0.125),
                                                                         scalar(0.125)},
                                    const vector3 &origin = vector3_zero);

// An open-top box of static boxes (floor and four walls, no ground needed) holding `layers`
// layers of spheres of `radius`, stacked as fruit is: `width` by `width` spheres in the even
// layers, filling the box wall to wall, and (width - 1) by (width - 1) in the odd ones, each
// sphere in the hollow between four below. The walls reach the top of the last full layer.
struct spheres_in_box_scene {
    std::vector<entity> container; // floor, then the walls
    std::vector<entity> spheres;   // layer by layer from the bottom
    // The inside of the box: the floor's top is at `origin.y`, the walls at `origin.x` and
    // `origin.z` plus or minus `inner_half_width`, their tops at `origin.y` + `wall_height`.
    scalar inner_half_width{0};
    scalar wall_height{0};
};
spheres_in_box_scene make_spheres_in_box(registry &registry, unsigned layers = 4, unsigned width = 4,
                                         scalar radius = scalar(0.25), const vector3 &origin = vector3_zero);

enum class pile_shapes : std::uint8_t {
    // Boxes, spheres, capsules and cylinders in equal share.
    primitives,
    // As primitives, plus convex polyhedra (a fifth of the bodies).
    with_polyhedra
};

// `count` mixed bodies of sizes 0.5 to 1 in a grid `width` bodies wide, dropped from above
// the ground (the layers start at `height` and go up 1.5 m each). Sizes and orientations come
// from a fixed-seed generator, so that the scene is the same on every run.
std::vector<entity> make_pile(registry &registry, unsigned count, unsigned width = 16, scalar height = 2,
                              pile_shapes shapes = pile_shapes::with_polyhedra, std::uint32_t seed = 1);

// A row of spheres of radius 0.5 dropped from `height`, with restitution going from 0 to 1
// in equal increments. The ground's restitution is 0 so each ball's own value sets its bounce
// (the mixed restitution is the larger of the two).
std::vector<entity> make_bouncing_balls(registry &registry, unsigned count, scalar height = 4,
                                        const vector3 &origin = vector3_zero);

// A chain of `links` boxes `link_length` long, joined end to end by point constraints and
// hanging from a static anchor at `top`. It is laid out horizontally along +x, so that it
// swings down when the simulation starts. Neighbouring links do not collide with each other.
struct chain_scene {
    entity anchor{null};
    std::vector<entity> links;
    std::vector<entity> joints; // joints[i] holds links[i] to the anchor (i = 0) or to links[i - 1]
};
chain_scene make_chain(registry &registry, unsigned links, scalar link_length = scalar(0.5),
                       const vector3 &top = {0, 10, 0});

// A rope bridge: `planks` planks `plank_length` long (along x) and 1 m wide (along z), joined
// by damped hinges about z at their ends, spanning between two static posts whose tops are at
// `height`. The deck starts at `origin` + (0, height, 0) and runs along +x, hanging slack in a
// shallow arc (2 degrees at each hinge), so it spans a little less than planks * plank_length.
// Neighbouring planks
// do not collide with each other nor the end planks with their posts.
struct bridge_scene {
    entity posts[2]{null, null};
    std::vector<entity> planks;
    std::vector<entity> hinges; // hinges[i] holds the start of planks[i]; the last one the end post
};
bridge_scene make_bridge(registry &registry, unsigned planks, scalar plank_length = scalar(0.5),
                         scalar height = 3, const vector3 &origin = vector3_zero);

// `count` rag dolls of 1.8 m and 80 kg dropped onto the ground: standing, each leaning a little
// its own way, `columns` by `columns` to a layer 2.8 m apart around `origin`, the lowest layer's
// feet `height` above it and each layer 2.2 m above the one below, turned a quarter turn.
std::vector<ragdoll_entities> make_ragdoll_pile(registry &registry, unsigned count, unsigned columns = 2,
                                                scalar height = scalar(0.5),
                                                const vector3 &origin = vector3_zero);

// Billiards on a static table 4 m by 2 m (its top at y = 0.8) with rails of restitution 0.8:
// fifteen balls of radius 0.1 m racked in a triangle and a cue ball rolling into them at
// `cue_speed` along +x. Ball on ball restitution is 0.95.
struct billiards_scene {
    entity table{null};
    std::vector<entity> rails;
    std::vector<entity> balls; // the rack, then the cue ball
    entity cue_ball{null};
};
billiards_scene make_billiards(registry &registry, scalar cue_speed = 4);

// A door (1 m by 2 m, 20 kg) on a hinge about y to a static post at `origin`, pushed open: its
// hinge has limits at +/-100 degrees with restitution 0.3 and a damped spring towards closed.
struct door_scene {
    entity post{null};
    entity door{null};
    entity hinge{null};
};
door_scene make_hinge_door(registry &registry, const vector3 &origin = vector3_zero);

// Three blocks on static rails along x, each held by a generic constraint free along x within
// +/-1.5 m and locked otherwise, launched at 4 m/s: the first bounces between the limits, the
// second is pulled back by a spring, the third is slowed by friction. Rails 1.2 m apart along z.
struct slider_scene {
    std::vector<entity> rails;
    std::vector<entity> blocks;
    std::vector<entity> joints;
};
slider_scene make_sliders(registry &registry, const vector3 &origin = vector3_zero);

// A car: a 600 kg box chassis, four wheels (cylinders of radius 0.4 about x) hinged to hubs, and
// each hub held to the chassis by a generic constraint free only up and down (the suspension: a
// damped spring within +/-0.2 m); the front hubs also turn about y, towards the rest angle that
// drive_vehicle sets. Index 0 and 1 are the front wheels (towards -z), 0 and 2 on the left (-x).
struct vehicle_scene {
    entity chassis{null};
    std::array<entity, 4> hubs{};
    std::array<entity, 4> wheels{};
    std::array<entity, 4> suspension{};
    std::array<entity, 4> axles{};
};
vehicle_scene make_vehicle(registry &registry, const vector3 &origin = vector3_zero);
// Steering in [-1, 1] (positive turns left) and throttle in [-1, 1] (positive drives towards -z,
// as a torque on the rear wheels over `dt` seconds). Call before each step or update.
void drive_vehicle(registry &registry, const vehicle_scene &vehicle, scalar throttle, scalar steering,
                   scalar dt);

// One body of each convex shape (box, sphere, capsule, cylinder, polyhedron) in a row along x,
// and three compounds behind them (a dumbbell, a table, an L of boxes and a capsule), dropped
// from 2 m above `origin`. Returns them in that order.
std::vector<entity> make_shape_gallery(registry &registry, const vector3 &origin = vector3_zero);

} // namespace edyn::scenes

#endif // EDYN_SCENES_SCENES_HPP
