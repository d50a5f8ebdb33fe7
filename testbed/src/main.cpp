// edyn-testbed: a window listing the samples by category and running one, with a panel of
// settings and timings; or, with --screenshot, one frame rendered off-screen to a PNG.
#include "app.hpp"
#include "gl.hpp"
#include "samples.hpp"
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace {

struct options {
    std::string scene{"pyramid"};
    unsigned steps{0};
    unsigned frames{0};
    std::string mode{"sequential"};
    std::string screenshot;
    std::string script;
    int width{0}, height{0};
    bool ui{false};
    bool debug{false};
    bool list{false};
};

void glfw_error(int code, const char *description) {
    std::fprintf(stderr, "edyn-testbed: GLFW error %d: %s\n", code, description);
}

void print_samples(std::FILE *out) {
    std::fprintf(out, "samples:\n");
    for (auto &s : testbed::all_samples())
        std::fprintf(out, "  %-16s %-10s %s\n", s.name.c_str(), s.category.c_str(), s.description.c_str());
}

bool software_renderer() {
    auto *name = reinterpret_cast<const char *>(glGetString(GL_RENDERER));
    std::string renderer = name ? name : "";
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

GLFWwindow *open_window(const options &opt, bool off_screen) {
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) {
        std::fprintf(stderr,
                     "edyn-testbed: no display to open a window on (DISPLAY is %s). Run it on a desktop, "
                     "or render off-screen with --screenshot FILE.png under xvfb-run -a.\n",
                     std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "not set");
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, off_screen ? 0 : 4);
    if (off_screen) glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    auto *window = glfwCreateWindow(opt.width, opt.height, "edyn testbed", nullptr, nullptr);
    if (window && !off_screen) {
        // Multisampling costs a software renderer about four times the frame: not worth it there.
        glfwMakeContextCurrent(window);
        if (software_renderer()) {
            glfwDestroyWindow(window);
            glfwWindowHint(GLFW_SAMPLES, 0);
            window = glfwCreateWindow(opt.width, opt.height, "edyn testbed", nullptr, nullptr);
        }
    }
    if (!window) {
        std::fprintf(stderr,
                     "edyn-testbed: cannot create an OpenGL 3.3 core context: this machine's OpenGL "
                     "driver does not offer it (on a server, install libgl1-mesa-dri for llvmpipe).\n");
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(off_screen ? 0 : 1);
    return window;
}

} // namespace

int main(int argc, char **argv) {
    options opt;
    CLI::App cli{"edyn-testbed: the samples of edyn, drawn and interactive"};
    cli.add_option("--scene", opt.scene, "sample to run (see --list)");
    cli.add_option("--steps", opt.steps, "with --screenshot: fixed steps to run before the picture")
        ->check(CLI::Range(0u, 100000u));
    cli.add_option("--screenshot", opt.screenshot, "render off-screen to this PNG file and exit");
    cli.add_option("--script", opt.script,
                   "with --screenshot: mouse actions played after --steps, one fixed step a frame, e.g. "
                   "\"press 400 200; move 400 100 30; wait 60; release; ray 300 250; shoot 400 225\"");
    cli.add_option("--width", opt.width, "window or image width in pixels")->check(CLI::Range(64, 8192));
    cli.add_option("--height", opt.height, "window or image height in pixels")->check(CLI::Range(64, 8192));
    cli.add_option("--frames", opt.frames, "in a window: quit after this many frames and print the timings");
    cli.add_option("--mode", opt.mode, "execution mode (in a window, the one it starts in)")
        ->check(CLI::IsMember({"sequential", "multithreaded", "asynchronous"}));
    cli.add_flag("--ui", opt.ui, "with --screenshot: draw the panel too");
    cli.add_flag("--debug", opt.debug, "start with contacts, normals, AABBs and islands drawn");
    cli.add_flag("--list", opt.list, "print the samples and exit");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::Success &e) {
        return cli.exit(e); // --help
    } catch (const CLI::ParseError &e) {
        // The usage with the error, not only CLI11's pointer to --help.
        std::fprintf(stderr, "edyn-testbed: %s\n\n%s", e.what(), cli.help().c_str());
        return 2;
    }

    if (opt.list) {
        print_samples(stdout);
        return 0;
    }
    auto *sample = testbed::find_sample(opt.scene);
    if (!sample) {
        std::fprintf(stderr, "edyn-testbed: no sample named '%s'\n", opt.scene.c_str());
        print_samples(stderr);
        return 2;
    }
    bool off_screen = !opt.screenshot.empty();
    if (opt.width == 0) opt.width = off_screen ? 800 : 1280;
    if (opt.height == 0) opt.height = off_screen ? 450 : 720;
    std::vector<testbed::script_command> script;
    if (!opt.script.empty()) {
        if (!off_screen) {
            std::fprintf(stderr, "edyn-testbed: --script needs --screenshot (it is played off-screen)\n");
            return 2;
        }
        try {
            script = testbed::parse_script(opt.script, opt.width, opt.height);
        } catch (const std::invalid_argument &e) {
            std::fprintf(stderr, "edyn-testbed: %s\n", e.what());
            return 2;
        }
    }

    auto *window = open_window(opt, off_screen);
    if (!window) return 3;
    int status = 0;
    try {
        testbed::app app(window, !off_screen || opt.ui);
        // Screenshots step one fixed step at a time and wait for it in every mode, so that the
        // check, re-running the steps sequentially, finds the same transforms.
        if (opt.mode == "multithreaded") app.settings.mode = edyn::execution_mode::sequential_multithreaded;
        if (opt.mode == "asynchronous") app.settings.mode = edyn::execution_mode::asynchronous;
        if (opt.debug) app.ctl.debug = {true, true, true, true, true};
        app.load(*sample);
        if (off_screen) {
            status = app.screenshot(opt.steps, script, opt.screenshot) ? 0 : 1;
            if (status == 0)
                std::printf("edyn-testbed: %s after %u steps written to %s\n", sample->name.c_str(),
                            opt.steps, opt.screenshot.c_str());
            if (status == 0 && app.stats.pages > 0 && opt.mode != "asynchronous")
                std::printf("edyn-testbed: %zu of %zu mesh pages loaded\n", app.stats.loaded_pages,
                            app.stats.pages);
        } else {
            app.run(opt.frames);
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "edyn-testbed: %s\n", e.what());
        status = 1;
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}
