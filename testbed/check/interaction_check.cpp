#include "interaction_check.hpp"
#include "body_colour.hpp"
#include "camera.hpp"
#include "script.hpp"
#include "world.hpp"
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace testbed {

namespace {

struct logged_ray {
    float x, y;
    edyn::entity body{edyn::null};
    edyn::vector3 point, normal, centre;
};

// Entities differ between execution modes (the asynchronous mode's main registry holds fewer):
// bodies are recognised by where they are.
struct logged_grab {
    edyn::entity body{edyn::null};
    edyn::vector3 point, centre;
};

// What the testbed printed.
struct script_log {
    std::vector<logged_ray> rays;
    std::vector<logged_grab> grabbed;
    std::vector<edyn::entity> balls;
    std::map<edyn::entity, edyn::vector3> end;
};

edyn::entity entity_of(unsigned index) { return edyn::entity{index}; }

std::optional<script_log> read_log(const std::string &path) {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    script_log log;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string tag, kind;
        if (!(words >> tag >> kind) || tag != "script:") continue;
        auto read_vector = [&](edyn::vector3 &v) { words >> v.x >> v.y >> v.z; };
        std::string word;
        unsigned index = 0;
        if (kind == "ray") {
            logged_ray r{};
            words >> r.x >> r.y >> word;
            if (word == "hit") {
                words >> index >> word;
                r.body = entity_of(index);
                read_vector(r.point);
                words >> word;
                read_vector(r.normal);
                words >> word;
                read_vector(r.centre);
            }
            log.rays.push_back(r);
        } else if (kind == "grabbed") {
            logged_grab g;
            words >> index >> word;
            g.body = entity_of(index);
            read_vector(g.point);
            words >> word;
            read_vector(g.centre);
            log.grabbed.push_back(g);
        } else if (kind == "ball") {
            words >> index;
            log.balls.push_back(entity_of(index));
        } else if (kind == "end") {
            edyn::vector3 p;
            words >> index >> word;
            read_vector(p);
            log.end[entity_of(index)] = p;
        }
        if (words.fail()) throw std::runtime_error("cannot read the log line '" + line + "'");
    }
    return log;
}

struct checker {
    int failures{0};
    void expect(bool ok, const char *what, const std::string &detail) {
        std::printf("%s %s: %s\n", ok ? "ok    " : "FAILED", what, detail.c_str());
        failures += !ok;
    }
};

std::string vec(const edyn::vector3 &v) {
    char text[96];
    std::snprintf(text, sizeof(text), "(%.3f %.3f %.3f)", double(v.x), double(v.y), double(v.z));
    return text;
}

} // namespace

int print_targets(const sample &s, unsigned steps, int width, int height) {
    sample_state state;
    auto registry = make_world(s, {}, state);
    run_steps(*registry, state, steps);
    edyn::entity top{edyn::null}, low{edyn::null};
    edyn::scalar top_y = -1e9, low_y = 1e9;
    for (auto body : registry->view<edyn::dynamic_tag>()) {
        auto &p = registry->get<edyn::position>(body);
        if (p.y > top_y) top_y = p.y, top = body;
        if (p.y < low_y) low_y = p.y;
    }
    if (top == edyn::null) return 1;
    float best = 1e9f;
    for (auto body : registry->view<edyn::dynamic_tag>()) {
        auto &p = registry->get<edyn::position>(body);
        if (p.y > low_y + edyn::scalar(0.05)) continue;
        auto q = project(s.camera, p, width, height);
        if (q.in_front && std::abs(q.x - float(width) / 2) < best)
            best = std::abs(q.x - float(width) / 2), low = body;
    }
    auto t = project(s.camera, registry->get<edyn::position>(top), width, height);
    auto b = project(s.camera, registry->get<edyn::position>(low), width, height);
    std::printf("%d %d %d %d\n", int(t.x), int(t.y), int(b.x), int(b.y));
    return 0;
}

int check_interaction(const sample &s, unsigned steps, const std::string &script, const std::string &log_path,
                      const image &img) {
    auto commands = parse_script(script, img.width, img.height);
    auto read = read_log(log_path);
    if (!read) {
        std::printf("cannot read %s\n", log_path.c_str());
        return 1;
    }
    auto &log = *read;
    // The world as the script found it: rays, the grab and the shot are aimed in it.
    sample_state state;
    auto registry = make_world(s, {}, state);
    run_steps(*registry, state, steps);
    auto &camera = s.camera;
    auto sight = [&](float x, float y) { return pixel_ray(camera, x, y, img.width, img.height); };
    auto cast = [&](const ray &r) {
        return edyn::raycast(*registry, r.origin, r.origin + r.direction * 500);
    };

    checker c;
    std::size_t next_ray = 0, next_ball = 0;
    std::optional<edyn::vector3> anchor; // where the drag holds the grab point at the end
    edyn::entity expected_grab{edyn::null};
    float cursor_x = 0, cursor_y = 0;
    edyn::scalar grab_distance = 0;
    for (auto &command : commands) {
        if (command.action == script_action::press || command.action == script_action::move ||
            command.action == script_action::ray) {
            cursor_x = command.x;
            cursor_y = command.y;
        }
        if (command.action == script_action::ray) {
            if (next_ray >= log.rays.size()) {
                c.expect(false, "ray", "the log has no line for it");
                continue;
            }
            auto &got = log.rays[next_ray++];
            auto r = sight(command.x, command.y);
            auto want = cast(r);
            auto want_point = r.origin + r.direction * (500 * want.fraction);
            auto want_centre =
                want.hit() ? edyn::vector3(registry->get<edyn::position>(want.entity)) : edyn::vector3_zero;
            bool ok = (got.body == edyn::null) == !want.hit();
            if (want.hit())
                ok = ok && edyn::distance(got.point, want_point) < edyn::scalar(0.01) &&
                     edyn::length(got.normal - want.normal) < edyn::scalar(0.01) &&
                     edyn::distance(got.centre, want_centre) < edyn::scalar(0.01) &&
                     edyn::dot(got.normal, r.direction) < 0;
            c.expect(ok, "ray",
                     "at pixel (" + std::to_string(int(command.x)) + ", " + std::to_string(int(command.y)) +
                         ") the testbed hit the body at " + vec(got.centre) + " at " + vec(got.point) +
                         " normal " + vec(got.normal) + ", the physics says the body at " + vec(want_centre) +
                         " at " + vec(want_point) + " normal " + vec(want.normal));
        }
        if (command.action == script_action::press) {
            auto r = sight(command.x, command.y);
            auto want = cast(r);
            expected_grab = want.entity;
            grab_distance = 500 * want.fraction;
        }
        if (command.action == script_action::release) expected_grab = edyn::null;
        if (command.action == script_action::shoot) {
            if (next_ball >= log.balls.size()) {
                c.expect(false, "shot", "the log has no ball for it");
                continue;
            }
            auto ball = log.balls[next_ball++];
            auto r = sight(command.x, command.y);
            auto want = cast(r);
            auto it = log.end.find(ball);
            bool ok = want.hit() && it != log.end.end();
            edyn::vector3 target = r.origin + r.direction * (500 * want.fraction);
            edyn::scalar off = ok ? edyn::distance(it->second, target) : 0;
            // Unhindered, the ball would fly on at 30 m/s: it ends near the body it was aimed at.
            c.expect(ok && off < 3, "shot",
                     "ball " + std::to_string(edyn::to_index(ball)) + " aimed at " + vec(target) + " ended " +
                         (it != log.end.end() ? vec(it->second) : std::string("nowhere")) + ", " +
                         std::to_string(off) + " m away (limit 3 m)");
        }
    }
    if (expected_grab != edyn::null) {
        auto r = sight(cursor_x, cursor_y);
        anchor = r.origin + r.direction * grab_distance;
        auto start = registry->get<edyn::position>(expected_grab);
        // Reported after the frame that attached the spring: the body has moved a step towards the
        // cursor by then, a centimetre or so; its neighbours are a metre away.
        bool grabbed =
            log.grabbed.size() == 1 && edyn::distance(log.grabbed[0].centre, start) < edyn::scalar(0.05);
        c.expect(
            grabbed, "grab",
            "the press grabbed " +
                (log.grabbed.empty() ? std::string("nothing") : "the body at " + vec(log.grabbed[0].centre)) +
                ", the body under the cursor was at " + vec(start));
        if (!grabbed) {
            std::printf("FAILED\n");
            return 1;
        }
        auto body = log.grabbed[0].body;
        auto it = log.end.find(body);
        // The grab point hangs at the anchor (a few centimetres of sag); the centre is within the
        // body's reach of it.
        auto reach = edyn::length(registry->get<edyn::AABB>(expected_grab).max - start);
        edyn::scalar off = it != log.end.end() ? edyn::distance(it->second, *anchor) : 1e9f;
        c.expect(off < reach + edyn::scalar(0.15) && edyn::distance(*anchor, start) > 1, "drag",
                 "the body started at " + vec(start) + ", was dragged to " + vec(*anchor) + " and ended " +
                     (it != log.end.end() ? vec(it->second) : std::string("nowhere")) + ", " +
                     std::to_string(off) + " m from the cursor (limit " + std::to_string(reach + 0.15f) +
                     ")");
        // Where the body ended (still swinging on the spring, above or below the cursor), the
        // picture shows it, in the colour its entity in the testbed's registry picks: a face of
        // the metre-wide box covers much of the window around its centre's pixel.
        auto colour = palette_colour(body);
        auto centre = it != log.end.end() ? project(s.camera, it->second, img.width, img.height)
                                          : projected_point{-1, -1, false};
        int px = int(centre.x), py = int(centre.y);
        constexpr int half_window = 6;
        int good = 0;
        for (int y = py - half_window; y <= py + half_window; ++y)
            for (int x = px - half_window; x <= px + half_window; ++x)
                good += centre.in_front && x >= 0 && y >= 0 && x < img.width && y < img.height &&
                        lit_match(img.at(x, y), colour);
        constexpr int window = (2 * half_window + 1) * (2 * half_window + 1);
        char detail[200];
        std::snprintf(
            detail, sizeof(detail),
            "%d of %d pixels around (%d, %d), where the body's centre ended, in its colour (%.2f %.2f %.2f)",
            good, window, px, py, double(colour.r), double(colour.g), double(colour.b));
        c.expect(good >= window / 3, "picture", detail);
    }
    std::printf(c.failures == 0 ? "ok\n" : "FAILED\n");
    return c.failures == 0 ? 0 : 1;
}

} // namespace testbed
