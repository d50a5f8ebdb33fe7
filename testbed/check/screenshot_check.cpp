// Checks a testbed screenshot against the physics: re-creates the sample, runs the same steps
// in sequential mode (deterministic, so the bodies are where the picture was taken), projects
// each body's centre with the sample's camera and checks the pixel there against the colour of
// the body seen along that line of sight, within a lighting tolerance; then checks that pixels
// whose lines of sight miss every body show the sky, and that the picture is not blank.
#include "body_colour.hpp"
#include "camera.hpp"
#include "image.hpp"
#include "interaction_check.hpp"
#include "samples.hpp"
#include "world.hpp"
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>

namespace {

using testbed::image;
using testbed::is_background;
using testbed::lit_match;

// Whether the line of sight through the pixel may meet a drawn body. A paged mesh counts
// wherever its bounds are: the testbed draws the pages it has seen loaded, which may be more
// than this run has loaded now.
bool sight_hits(const edyn::registry &registry, const testbed::orbit_camera &camera, float x, float y, int w,
                int h) {
    auto r = testbed::pixel_ray(camera, x, y, w, h);
    auto p1 = r.origin + r.direction * edyn::scalar(1000);
    if (edyn::raycast(registry, r.origin, p1).hit()) return true;
    for (auto [e, shape] : registry.view<edyn::paged_mesh_shape>().each()) {
        (void)e;
        if (edyn::intersect_segment(shape.trimesh->get_aabb(), r.origin, p1)) return true;
    }
    return false;
}

// Pixels whose line of sight first meets a triangle mesh or a loaded page of a paged mesh: the
// terrain's colour must be there. Returns {checked, matched}.
std::pair<unsigned, unsigned> check_terrain(const edyn::registry &registry,
                                            const testbed::orbit_camera &camera, const image &img) {
    unsigned checked = 0, matched = 0;
    for (int y = 8; y < img.height - 8; y += 16) {
        for (int x = 8; x < img.width - 8; x += 16) {
            auto r = testbed::pixel_ray(camera, float(x) + 0.5f, float(y) + 0.5f, img.width, img.height);
            auto hit = edyn::raycast(registry, r.origin, r.origin + r.direction * edyn::scalar(1000));
            if (!hit.hit() || !registry.any_of<edyn::mesh_shape, edyn::paged_mesh_shape>(hit.entity))
                continue;
            ++checked;
            matched += testbed::lit_matches_around(img, x, y, testbed::terrain_colour) >= 5;
        }
    }
    return {checked, matched};
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
    std::string script, log_path;
    bool targets = false;
    int width = 800, height = 450;
    cli.add_option("--script", script, "the mouse script the testbed played (checks what it did)");
    cli.add_option("--log", log_path, "with --script: the testbed's output, its \"script:\" lines");
    cli.add_flag("--print-targets", targets,
                 "no picture: print the pixels of the highest body and of a lowest one, \"TX TY BX BY\"");
    cli.add_option("--width", width, "with --print-targets: image width")->check(CLI::Range(64, 8192));
    cli.add_option("--height", height, "with --print-targets: image height")->check(CLI::Range(64, 8192));
    CLI11_PARSE(cli, argc, argv);
    if (all) return check_all_samples(steps);
    auto *sample = testbed::find_sample(scene);
    if (!sample) {
        std::fprintf(stderr, "no sample named '%s' (samples: %s)\n", scene.c_str(),
                     testbed::sample_names().c_str());
        return 2;
    }
    if (targets) return testbed::print_targets(*sample, steps, width, height);
    if (path.empty()) {
        std::fprintf(stderr, "--image is needed (or --all-samples, or --print-targets)\n");
        return 2;
    }
    image img;
    if (!img.load(path)) {
        std::fprintf(stderr, "cannot read %s\n", path.c_str());
        return 1;
    }

    if (!script.empty()) {
        if (log_path.empty()) {
            std::fprintf(stderr, "--script needs --log\n");
            return 2;
        }
        try {
            return testbed::check_interaction(*sample, steps, script, log_path, img);
        } catch (const std::exception &e) {
            std::fprintf(stderr, "%s\n", e.what());
            return 1;
        }
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
        int good = testbed::lit_matches_around(img, px, py, expected);
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
    auto [terrain_checked, terrain_matched] = check_terrain(*registry, camera, img);
    if (terrain_checked > 0)
        std::printf("%u of %u terrain samples in the terrain's colour\n", terrain_matched, terrain_checked);
    double drawn = double(not_background) / (double(img.width) * img.height);
    std::printf("%s after %u steps: %u of %u body centres in their body's colour, %u of %u sky samples "
                "background, %.1f%% of the image drawn\n",
                scene.c_str(), steps, matched, checked, sky_matched, sky_checked, 100 * drawn);
    bool ok = checked >= 5 && matched >= checked * 9 / 10 && sky_checked >= 10 &&
              sky_matched == sky_checked && drawn > 0.05 && terrain_matched >= terrain_checked * 9 / 10;
    std::printf(ok ? "ok\n"
                   : "FAILED (need 5 or more centres checked, 90%% matching, 10 or more sky samples all "
                     "background, 5%% drawn, 90%% of terrain samples matching)\n");
    return ok ? 0 : 1;
}
