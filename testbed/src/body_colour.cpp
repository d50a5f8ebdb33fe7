#include "body_colour.hpp"
#include "samples.hpp"
#include <algorithm>
#include <array>

namespace testbed {

namespace {

// Saturated and far apart in hue, so that neighbours read apart and the screenshot check can
// tell one body's colour from another's and from the sky and the ground.
constexpr std::array<colour, 8> palette{{
    {0.90f, 0.30f, 0.25f},
    {0.95f, 0.65f, 0.15f},
    {0.35f, 0.75f, 0.30f},
    {0.25f, 0.45f, 0.90f},
    {0.75f, 0.35f, 0.85f},
    {0.20f, 0.75f, 0.75f},
    {0.95f, 0.85f, 0.25f},
    {0.85f, 0.40f, 0.60f},
}};

} // namespace

colour palette_colour(edyn::entity body) {
    // The entity's index picks the colour: the same scene gets the same colours every run.
    // Mixed, so that bodies made in a regular order do not repeat a short cycle.
    auto index = std::uint32_t(edyn::to_index(body)) * 2654435761u;
    return palette[(index >> 16) % palette.size()];
}

colour body_colour(const edyn::registry &registry, edyn::entity body, bool grey_sleeping) {
    if (auto *tint = registry.try_get<body_tint>(body); tint && registry.all_of<edyn::static_tag>(body))
        return {tint->r, tint->g, tint->b};
    if (registry.all_of<edyn::static_tag>(body)) return {0.55f, 0.52f, 0.48f};
    if (grey_sleeping && registry.all_of<edyn::sleeping_tag>(body)) return {0.62f, 0.62f, 0.62f};
    colour c;
    if (auto *tint = registry.try_get<body_tint>(body)) {
        c = {tint->r, tint->g, tint->b};
    } else {
        c = palette_colour(body);
    }
    if (auto *flash = registry.try_get<body_flash>(body); flash && flash->time_left > 0) {
        auto t = std::min(flash->time_left / 0.3f, 1.0f);
        c = {c.r + (1 - c.r) * t, c.g + (1 - c.g) * t, c.b + (1 - c.b) * t};
    }
    return c;
}

} // namespace testbed
