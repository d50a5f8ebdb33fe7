// Checks a testbed screenshot against the physics: re-creates the sample, runs the same steps
// in sequential mode (deterministic, so the bodies are where the picture was taken), projects
// each body's centre with the sample's camera and checks the pixel there against the colour of
// the body seen along that line of sight, within a lighting tolerance; then checks that pixels
// whose lines of sight miss every body show the sky, and that the picture is not blank.
#include "body_colour.hpp"
#include "camera.hpp"
#include "samples.hpp"
#include "world.hpp"
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stb_image.h>

namespace {

struct image {
    int width{0}, height{0};
    std::unique_ptr<unsigned char, void (*)(void *)> pixels{nullptr, stbi_image_free};
    testbed::colour at(int x, int y) const {
        auto *p = pixels.get() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
        return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
    }
};

// Lit colours are the body's colour times a light factor (the shader's 0.4 to 1.0): the pixel
// must be close to some such multiple.
bool lit_match(testbed::colour pixel, testbed::colour base) {
    float dot_pc = pixel.r * base.r + pixel.g * base.g + pixel.b * base.b;
    float dot_cc = base.r * base.r + base.g * base.g + base.b * base.b;
    float k = dot_pc / dot_cc;
    if (k < 0.3f || k > 1.1f) return false;
    float worst = std::max(
        {std::abs(pixel.r - k * base.r), std::abs(pixel.g - k * base.g), std::abs(pixel.b - k * base.b)});
    return worst < 0.06f;
}

bool is_background(testbed::colour pixel) {
    auto bg = testbed::background_colour;
    return std::abs(pixel.r - bg.r) < 0.015f && std::abs(pixel.g - bg.g) < 0.015f &&
           std::abs(pixel.b - bg.b) < 0.015f;
}

// Whether the line of sight through the pixel meets any body.
bool sight_hits(const edyn::registry &registry, const testbed::orbit_camera &camera, float x, float y, int w,
                int h) {
    auto r = testbed::pixel_ray(camera, x, y, w, h);
    return edyn::raycast(registry, r.origin, r.origin + r.direction * edyn::scalar(1000)).hit();
}

} // namespace

// Every sample builds and runs `steps` steps with its bodies' positions finite and none fallen
// far through the floor.
int check_all_samples(unsigned steps) {
    int failures = 0;
    for (auto &s : testbed::all_samples()) {
        testbed::sample_state state;
        auto registry = testbed::make_world(s, {}, state);
        testbed::run_steps(*registry, state, steps);
        unsigned bodies = 0, bad = 0;
        for (auto body : registry->view<edyn::dynamic_tag>()) {
            auto &p = registry->get<edyn::position>(body);
            ++bodies;
            bad += !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && p.y > -5);
        }
        std::printf("%-16s %5u bodies, %u out of place after %u steps\n", s.name.c_str(), bodies, bad, steps);
        failures += bodies == 0 || bad > 0;
    }
    return failures == 0 ? 0 : 1;
}

int main(int argc, char **argv) {
    std::string scene, path;
    unsigned steps = 0;
    bool all = false;
    CLI::App cli{"edyn-testbed-check: a testbed screenshot against the physics"};
    cli.add_option("--scene", scene, "the sample of the screenshot");
    cli.add_option("--steps", steps, "the steps it was taken after")->required();
    cli.add_option("--image", path, "the PNG file");
    cli.add_flag("--all-samples", all, "no picture: run every sample for --steps and check its bodies");
    CLI11_PARSE(cli, argc, argv);
    if (all) return check_all_samples(steps);
    if (scene.empty() || path.empty()) {
        std::fprintf(stderr, "--scene and --image are needed (or --all-samples)\n");
        return 2;
    }

    auto *sample = testbed::find_sample(scene);
    if (!sample) {
        std::fprintf(stderr, "no sample named '%s' (samples: %s)\n", scene.c_str(),
                     testbed::sample_names().c_str());
        return 2;
    }
    image img;
    int channels = 0;
    img.pixels.reset(stbi_load(path.c_str(), &img.width, &img.height, &channels, 3));
    if (!img.pixels) {
        std::fprintf(stderr, "cannot read %s\n", path.c_str());
        return 1;
    }

    testbed::sample_state state;
    auto registry = testbed::make_world(*sample, {}, state);
    testbed::run_steps(*registry, state, steps);
    auto &camera = sample->camera;
    auto eye = camera.eye();

    unsigned checked = 0, matched = 0;
    for (auto body : registry->view<edyn::dynamic_tag, edyn::shape_index>()) {
        edyn::vector3 centre = registry->get<edyn::present_position>(body);
        auto p = testbed::project(camera, centre, img.width, img.height);
        int px = int(p.x), py = int(p.y);
        if (!p.in_front || px < 1 || py < 1 || px >= img.width - 1 || py >= img.height - 1) continue;
        // The body seen along the line of sight through the centre: the one drawn there.
        auto dir = edyn::normalize(centre - eye);
        auto hit = edyn::raycast(*registry, eye, centre + dir * edyn::scalar(0.01));
        if (!hit.hit()) continue; // a centre in empty space (a compound's)
        auto expected = testbed::body_colour(*registry, hit.entity, false);
        int good = 0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                good += lit_match(img.at(px + dx, py + dy), expected);
        ++checked;
        if (good >= 5) {
            ++matched;
        } else {
            auto c = img.at(px, py);
            std::printf(
                "body %u at pixel (%d, %d): expected a shade of (%.2f %.2f %.2f), found (%.2f %.2f %.2f)\n",
                unsigned(edyn::to_index(hit.entity)), px, py, double(expected.r), double(expected.g),
                double(expected.b), double(c.r), double(c.g), double(c.b));
        }
    }

    unsigned sky_checked = 0, sky_matched = 0, not_background = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            not_background += !is_background(img.at(x, y));
    for (int y = 8; y < img.height - 8; y += 16) {
        for (int x = 8; x < img.width - 8; x += 16) {
            // Far from every body: neither this line of sight nor those 6 pixels around it meet one.
            bool far = true;
            for (auto [dx, dy] : {std::pair{0, 0}, {-6, 0}, {6, 0}, {0, -6}, {0, 6}})
                far = far && !sight_hits(*registry, camera, float(x + dx) + 0.5f, float(y + dy) + 0.5f,
                                         img.width, img.height);
            if (!far) continue;
            ++sky_checked;
            sky_matched += is_background(img.at(x, y));
        }
    }
    double drawn = double(not_background) / (double(img.width) * img.height);
    std::printf("%s after %u steps: %u of %u body centres in their body's colour, %u of %u sky samples "
                "background, %.1f%% of the image drawn\n",
                scene.c_str(), steps, matched, checked, sky_matched, sky_checked, 100 * drawn);
    bool ok = checked >= 5 && matched >= checked * 9 / 10 && sky_checked >= 10 &&
              sky_matched == sky_checked && drawn > 0.05;
    std::printf(ok ? "ok\n"
                   : "FAILED (need 5 or more centres checked, 90%% matching, 10 or more sky samples all "
                     "background, 5%% drawn)\n");
    return ok ? 0 : 1;
}
