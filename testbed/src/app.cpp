#include "app.hpp"
#include "body_colour.hpp"
#include "gl.hpp"
#include "scene_draw.hpp"
#include "screenshot.hpp"
#include "ui_panel.hpp"
#include <algorithm>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <chrono>
#include <cstdio>
#include <imgui.h>

namespace testbed {

namespace {

using clock_type = std::chrono::steady_clock;

double ms_since(clock_type::time_point start) {
    return std::chrono::duration<double, std::milli>(clock_type::now() - start).count();
}

// About five seconds of frames at 60 fps.
constexpr std::size_t history_length = 300;

void key_callback(GLFWwindow *window, int key, int, int action, int mods) {
    static_cast<app *>(glfwGetWindowUserPointer(window))->on_key(key, action, mods);
}

} // namespace

app::app(GLFWwindow *w, bool ui)
    : window(w)
    , with_ui(ui) {
    gfx = std::make_unique<renderer>();
    glfwSetWindowUserPointer(window, this);
    // Set before ImGui's backend installs its own, which then calls this one too.
    glfwSetKeyCallback(window, key_callback);
    if (with_ui) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        ImGui::StyleColorsDark();
        ImGui::GetStyle().Alpha = 0.92f;
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 330 core");
    }
}

app::~app() {
    if (registry) dragger.release(*registry);
    // The registry first: raycast replies still pending point at the dragger and the probe.
    registry.reset();
    gfx.reset();
    if (with_ui) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
}

void app::load(const sample &s) {
    bool same = current == &s;
    if (registry) dragger.release(*registry);
    registry.reset(); // detaches: the asynchronous worker stops here, pending rays are dropped
    dragger.forget();
    gfx->forget_meshes();
    registry = make_world(s, settings, state);
    current = &s;
    if (!same) camera = s.camera; // a reset keeps the view the user chose
    sim_clock = 0;
    edyn::update(*registry, sim_clock);
    stats.step_history.clear();
    probe.clear();
}

void app::apply_settings() {
    if (registry) testbed::apply_settings(*registry, settings);
}

void app::on_key(int key, int action, int) {
    if (action != GLFW_PRESS) return;
    if (with_ui && ImGui::GetIO().WantCaptureKeyboard) return;
    auto &d = ctl.debug;
    switch (key) {
    case GLFW_KEY_P:
        ctl.paused = !ctl.paused;
        break;
    case GLFW_KEY_S:
        ctl.step_once = true;
        break;
    case GLFW_KEY_R:
        ctl.reset = true;
        break;
    case GLFW_KEY_M:
        ctl.slow_motion = !ctl.slow_motion;
        break;
    case GLFW_KEY_C:
        d.contacts = !d.contacts;
        break;
    case GLFW_KEY_N:
        d.normals = !d.normals;
        break;
    case GLFW_KEY_A:
        d.aabbs = !d.aabbs;
        break;
    case GLFW_KEY_I:
        d.islands = !d.islands;
        break;
    case GLFW_KEY_Y:
        ctl.show_ray = !ctl.show_ray;
        break;
    case GLFW_KEY_TAB:
        ctl.show_panel = !ctl.show_panel;
        break;
    case GLFW_KEY_ESCAPE:
        glfwSetWindowShouldClose(window, GLFW_TRUE);
        break;
    case GLFW_KEY_B: {
        int w = 0, h = 0;
        double x = 0, y = 0;
        glfwGetWindowSize(window, &w, &h);
        glfwGetCursorPos(window, &x, &y);
        if (w > 0 && h > 0) shoot_ball(*registry, pixel_ray(camera, float(x), float(y), w, h));
        break;
    }
    default:
        break;
    }
}

sample_input app::keyboard_input() const {
    sample_input in;
    if (with_ui && ImGui::GetIO().WantCaptureKeyboard) return in;
    auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
    in.throttle = down(GLFW_KEY_UP) - down(GLFW_KEY_DOWN);
    in.steering = down(GLFW_KEY_LEFT) - down(GLFW_KEY_RIGHT);
    return in;
}

pointer_state app::read_pointer() const {
    pointer_state p;
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    p.x = float(x);
    p.y = float(y);
    p.left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    p.right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    p.middle = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    p.shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
    if (with_ui) {
        p.captured = ImGui::GetIO().WantCaptureMouse;
        p.wheel = ImGui::GetIO().MouseWheel;
    }
    return p;
}

void app::handle_pointer(const pointer_state &p, int width, int height) {
    auto dx = p.x - last_pointer.x, dy = p.y - last_pointer.y;
    bool was_down = last_pointer.left;
    last_pointer = p;
    auto cursor_ray = pixel_ray(camera, p.x, p.y, width, height);

    // A grab's hit cast in an earlier frame becomes a spring now.
    dragger.poll(*registry);
    if (p.left && !was_down && !p.captured) dragger.grab(*registry, cursor_ray);
    if (p.left && dragger.dragging()) dragger.drag(*registry, cursor_ray);
    if (!p.left) dragger.release(*registry);

    if (!p.captured) {
        if (p.middle || (p.right && p.shift)) {
            camera.pan(dx, dy, float(height));
        } else if (p.right) {
            camera.orbit(dx, dy);
        }
        if (p.wheel != 0) camera.zoom(p.wheel);
    }
    if (ctl.show_ray && !p.captured) {
        probe.cast(*registry, cursor_ray);
    } else {
        probe.clear();
    }
}

void app::step_physics(double frame_dt) {
    auto &r = *registry;
    bool asynchronous = settings.mode == edyn::execution_mode::asynchronous;
    double sim_dt = 0;
    if (!ctl.paused) sim_dt = std::min(frame_dt, 0.1) * (ctl.slow_motion ? ctl.slow_factor : 1.0);
    if (state.on_frame) state.on_frame(r, keyboard_input(), float(sim_dt));

    auto steps_before = edyn::get_step_count(r);
    auto start = clock_type::now();
    if (ctl.step_once) {
        edyn::step_simulation(r);
        if (asynchronous) edyn::wait_for_simulation(r);
        ctl.step_once = false;
    } else if (!ctl.paused || asynchronous) {
        sim_clock += sim_dt;
        edyn::update(r, sim_clock);
    }
    stats.physics_ms = ms_since(start);
    stats.steps = unsigned(edyn::get_step_count(r) - steps_before);
    if (stats.steps > 0 && !asynchronous) {
        stats.ms_per_step = stats.physics_ms / stats.steps;
        stats.step_history.push_back(float(stats.ms_per_step));
        if (stats.step_history.size() > history_length) stats.step_history.pop_front();
    }
}

void app::gather_stats() {
    auto &r = *registry;
    stats.bodies = r.storage<edyn::rigidbody_tag>().size();
    stats.manifolds = stats.contact_points = 0;
    r.view<edyn::contact_manifold>().each([&](const edyn::contact_manifold &m) {
        ++stats.manifolds;
        stats.contact_points += m.num_points;
    });
    stats.islands = r.storage<edyn::island>().size();
    stats.sleeping_islands = 0;
    for (auto e : r.view<edyn::island, edyn::sleeping_tag>()) {
        (void)e;
        ++stats.sleeping_islands;
    }
    stats.pages = stats.loaded_pages = 0;
    for (auto [e, shape] : r.view<edyn::paged_mesh_shape>().each()) {
        (void)e;
        stats.pages += shape.trimesh->num_pages();
        // The worker loads and unloads them in asynchronous mode: not read from here then.
        if (settings.mode != edyn::execution_mode::asynchronous)
            stats.loaded_pages += shape.trimesh->num_loaded_pages();
    }
}

void app::draw_frame(int width, int height, bool ui) {
    auto start = clock_type::now();
    glClearColor(background_colour.r, background_colour.g, background_colour.b, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    auto aspect = float(width) / float(std::max(height, 1));
    gfx->begin(camera.projection(aspect) * camera.view(), width, height);
    draw_bodies(*registry, *gfx, ctl.debug.grey_sleeping);
    draw_debug(*registry, *gfx, ctl.debug);
    if (dragger.dragging() && registry->valid(dragger.body())) {
        auto from = dragger.anchor_position(*registry);
        add_line(*gfx, from, dragger.grab_point(*registry), 1, 1, 1);
        add_cross(*gfx, from, 0.1f, 1, 1, 1);
    }
    if (probe.last.body != edyn::null) {
        add_cross(*gfx, probe.last.point, 0.15f, 0.1f, 1, 1);
        add_line(*gfx, probe.last.point, probe.last.point + probe.last.normal, 1, 0.2f, 1);
    }
    stats.draw_lists_ms = ms_since(start);
    gfx->draw();
    stats.draw_calls = gfx->draw_calls();
    if (with_ui) {
        if (ui) draw_panel(*this);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    // Wait for the frame to be rasterised, so that the drawing time includes the GPU's (or,
    // under a software renderer, the CPU's) share.
    glFinish();
    stats.draw_ms = ms_since(start);
}

void app::run(unsigned max_frames) {
    auto last = clock_type::now();
    unsigned frames = 0, steps = 0;
    double physics = 0, draw = 0, lists = 0, total = 0;
    while (!glfwWindowShouldClose(window) && (max_frames == 0 || frames < max_frames)) {
        auto frame_start = clock_type::now();
        double frame_dt = std::chrono::duration<double>(frame_start - last).count();
        last = frame_start;
        glfwPollEvents();
        if (with_ui) {
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
        }
        if (requested) {
            load(*requested);
            requested = nullptr;
        } else if (ctl.reset) {
            load(*current);
        }
        ctl.reset = false;
        int w = 0, h = 0, fw = 0, fh = 0;
        glfwGetWindowSize(window, &w, &h);
        glfwGetFramebufferSize(window, &fw, &fh);
        if (w > 0 && h > 0) handle_pointer(read_pointer(), w, h);
        step_physics(frame_dt);
        if (state.follow != edyn::null && registry->valid(state.follow)) {
            // Ease towards the followed body so that the view does not shake with it.
            edyn::vector3 at = registry->get<edyn::present_position>(state.follow);
            camera.target += (at - camera.target) * edyn::scalar(std::min(1.0, frame_dt * 4));
        }
        gather_stats();
        draw_frame(fw, fh, ctl.show_panel);
        glfwSwapBuffers(window);
        stats.frame_ms = ms_since(frame_start);
        ++frames;
        steps += stats.steps;
        physics += stats.physics_ms;
        draw += stats.draw_ms;
        lists += stats.draw_lists_ms;
        total += stats.frame_ms;
    }
    if (frames == 0) return;
    std::printf("%s: %u frames, %.1f ms a frame (%.0f fps): physics %.1f ms (%u steps, %.2f ms a step), "
                "drawing %.1f ms (%.1f ms of it building lists, %d draw calls), %zu bodies\n",
                current->name.c_str(), frames, total / frames, 1000 * frames / total, physics / frames, steps,
                steps ? physics / steps : 0.0, draw / frames, lists / frames, stats.draw_calls, stats.bodies);
}

void app::script_frame(const pointer_state &p, int width, int height) {
    handle_pointer(p, width, height);
    // One step, waited for: in asynchronous mode the worker has run it, and in every mode a ray
    // cast in this frame is answered before the next.
    run_steps(*registry, state, 1);
}

void app::play_script(const std::vector<script_command> &script, int width, int height) {
    auto print_vector = [](const edyn::vector3 &v) {
        std::printf(" %.4f %.4f %.4f", double(v.x), double(v.y), double(v.z));
    };
    pointer_state p = last_pointer;
    std::vector<edyn::entity> reported; // grabbed bodies and balls, whose final place is printed
    auto report_grab = [&] {
        auto body = dragger.body();
        if (body == edyn::null || std::find(reported.begin(), reported.end(), body) != reported.end()) return;
        reported.push_back(body);
        std::printf("script: grabbed %u at", unsigned(edyn::to_integral(body)));
        print_vector(dragger.grab_point(*registry));
        std::printf(" centre");
        print_vector(registry->get<edyn::position>(body));
        std::printf("\n");
    };
    auto frame = [&] {
        script_frame(p, width, height);
        report_grab();
    };
    for (auto &c : script) {
        switch (c.action) {
        case script_action::press:
            p.x = c.x;
            p.y = c.y;
            p.left = true;
            frame();
            break;
        case script_action::move: {
            auto x0 = p.x, y0 = p.y;
            for (unsigned i = 1; i <= c.frames; ++i) {
                auto t = float(i) / float(c.frames);
                p.x = x0 + (c.x - x0) * t;
                p.y = y0 + (c.y - y0) * t;
                frame();
            }
            break;
        }
        case script_action::release:
            p.left = false;
            frame();
            break;
        case script_action::wait:
            for (unsigned i = 0; i < c.frames; ++i)
                frame();
            break;
        case script_action::ray:
            p.x = c.x;
            p.y = c.y;
            ctl.show_ray = true;
            frame();
            if (probe.last.body == edyn::null) {
                std::printf("script: ray %.1f %.1f miss\n", double(c.x), double(c.y));
            } else {
                std::printf("script: ray %.1f %.1f hit %u at", double(c.x), double(c.y),
                            unsigned(edyn::to_integral(probe.last.body)));
                print_vector(probe.last.point);
                std::printf(" normal");
                print_vector(probe.last.normal);
                std::printf(" centre");
                print_vector(registry->valid(probe.last.body)
                                 ? edyn::vector3(registry->get<edyn::position>(probe.last.body))
                                 : edyn::vector3_zero);
                std::printf("\n");
            }
            // Shown for this frame only: its marker would cover what the picture is checked for.
            ctl.show_ray = false;
            break;
        case script_action::shoot: {
            auto ball = shoot_ball(*registry, pixel_ray(camera, c.x, c.y, width, height));
            reported.push_back(ball);
            std::printf("script: ball %u through %.1f %.1f\n", unsigned(edyn::to_integral(ball)), double(c.x),
                        double(c.y));
            break;
        }
        }
    }
    for (auto body : reported) {
        if (!registry->valid(body)) continue;
        std::printf("script: end %u at", unsigned(edyn::to_integral(body)));
        print_vector(registry->get<edyn::present_position>(body));
        std::printf("\n");
    }
}

bool app::screenshot(unsigned steps, const std::vector<script_command> &script, const std::string &path) {
    stats.physics_ms = 0;
    run_steps(*registry, state, steps, [&](double ms) {
        stats.physics_ms += ms;
        stats.step_history.push_back(float(ms));
        if (stats.step_history.size() > history_length) stats.step_history.pop_front();
    });
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    if (!script.empty()) play_script(script, w, h);
    // The panel shows a frame of 60 Hz: one step, of the average time.
    stats.ms_per_step = steps ? stats.physics_ms / steps : 0;
    stats.physics_ms = stats.ms_per_step;
    stats.steps = steps ? 1 : 0;
    gather_stats();
    // ImGui sizes a new window in its first frame and shows it from the second; the third shows
    // the drawing time of a frame after the first (whose time includes compiling shaders).
    for (int frame = 0; frame < (with_ui ? 3 : 1); ++frame) {
        if (with_ui) {
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
        }
        draw_frame(w, h, with_ui);
        stats.frame_ms = stats.physics_ms + stats.draw_ms;
    }
    return write_screenshot(path, w, h);
}

} // namespace testbed
