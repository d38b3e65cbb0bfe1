#include "app/view/view_server.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "app/compare/reference_image.h"
#include "app/demo/demo_list.h"
#include "app/demo/demo_size.h"
#include "app/demo/label_text.h"
#include "app/trace/pixel_trace.h"
#include "app/view/display_pixels.h"
#include "app/view/file_stamps.h"
#include "app/view/page_assets.h"
#include "app/view/program_restart.h"
#include "app/view/reference_files.h"
#include "app/view/scene_controls.h"
#include "app/view/view_session.h"
#include "base/errors/input_error.h"

namespace raystep {

namespace {

using nlohmann::json;

// Set by Ctrl-C (SIGINT) or SIGTERM; the watch loop stops the server, since a signal handler may
// do no more than set a flag.
volatile std::sig_atomic_t g_stop_signal = 0;

void on_stop_signal(int) {
    g_stop_signal = 1;
}

// How often the watch loop looks at the scene's files and the program's.
constexpr std::chrono::milliseconds kWatchPeriod{250};

// Every /api/ request must carry this header. A page of another site can make the browser send a
// plain GET to 127.0.0.1, but not with a header of its own without a CORS preflight, which this
// server never grants: only the page it serves drives it.
constexpr const char* kApiHeader = "X-Raystep";

// JSON text of `value`. A byte that is not UTF-8 (a Latin-1 scene line echoed in an error, a file
// name under scenes/, a request's parameter) becomes U+FFFD rather than an exception: the page
// still gets its answer and can show the rest.
std::string json_text(const json& value) {
    return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

void send_json(httplib::Response& response, const json& body, int status = 200) {
    response.status = status;
    response.set_content(json_text(body), "application/json");
}

void send_error(httplib::Response& response, int status, const std::string& message) {
    send_json(response, json{{"error", message}}, status);
}

// A binary frame of images for the page: the JSON header's length as 4 bytes, little end first,
// the header, then each rectangle's pixels in the header's order (display_pixels.h). The page
// draws them straight into a canvas.
void send_frame(httplib::Response& response, json header,
                const std::vector<LiveRender::Tile>& tiles) {
    json rects = json::array();
    std::size_t bytes = 0;
    for (const LiveRender::Tile& tile : tiles) {
        rects.push_back(
            {tile.rect.x0, tile.rect.y0, tile.rect.x1 - tile.rect.x0, tile.rect.y1 - tile.rect.y0});
        bytes += tile.pixels.size();
    }
    header["tiles"] = std::move(rects);
    const std::string text = json_text(header);
    std::string body;
    body.reserve(4 + text.size() + bytes);
    const auto length = static_cast<std::uint32_t>(text.size());
    for (int k = 0; k < 4; ++k)
        body.push_back(static_cast<char>((length >> (8 * k)) & 0xffu));
    body += text;
    for (const LiveRender::Tile& tile : tiles)
        body += tile.pixels;
    response.set_content(body, "application/octet-stream");
}

int integer_parameter(const httplib::Request& request, const char* name) {
    const std::string text = request.get_param_value(name);
    std::size_t used = 0;
    int value = 0;
    try {
        value = std::stoi(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (text.empty() || used != text.size()) {
        throw std::invalid_argument(std::string(name) + ": '" + text + "' is not a whole number");
    }
    return value;
}

std::uint64_t counter_parameter(const httplib::Request& request, const char* name) {
    const std::string text = request.get_param_value(name);
    if (text.empty()) return 0;
    if (text.find_first_not_of("0123456789") != std::string::npos || text.size() > 19) {
        throw std::invalid_argument(std::string(name) + ": '" + text + "' is not a counter");
    }
    return std::stoull(text);
}

View view_parameter(const httplib::Request& request) {
    const std::string name = request.get_param_value("view");
    const std::optional<View> view = parse_view(name.empty() ? "full" : name);
    if (!view) throw std::invalid_argument("view: no view '" + name + "'");
    return *view;
}

// The controls of scene_controls.h among a request's parameters.
std::map<std::string, std::string> control_values(const httplib::Request& request) {
    std::map<std::string, std::string> values;
    for (const char* name : {"offset", "epsilon", "spp", "pixelsampling", "seed", "lightsamples",
                             "lightstratify", "ior"}) {
        if (request.has_param(name)) values[name] = request.get_param_value(name);
    }
    return values;
}

json controls_json(const Scene& scene) {
    json controls = json::array();
    for (const SceneControl& control : scene_controls(scene)) {
        controls.push_back({{"name", control.name},
                            {"label", control.label},
                            {"kind", control.kind},
                            {"choices", control.choices},
                            {"value", control.scene_value}});
    }
    return controls;
}

json scene_json(const ViewSession& session, const ReferenceFiles& references) {
    const std::string file = session.scene_file();
    json scene{{"file", file}, {"generation", session.scene_generation()}};
    const std::optional<Scene> loaded = session.scene();
    if (!loaded) {
        scene["error"] = file.empty() ? "" : session.load_error();
        return scene;
    }
    // The view the scene's `# views:` line names first: a stage-2 scene opens on rays, which
    // stages 1 and 2 alone can render.
    std::vector<std::string> views{"full"};
    try {
        views = reference_views(file);
    } catch (const InputError&) {
        // A `# views:` line naming no view: the page opens on full.
    }
    scene["first_view"] = views.empty() ? "full" : views.front();
    scene["width"] = loaded->width;
    scene["height"] = loaded->height;
    json notes = json::array();
    for (const SceneNote& note : loaded->notes)
        notes.push_back(warning_text(*loaded, note));
    scene["notes"] = notes;
    scene["controls"] = controls_json(*loaded);
    scene["reference_views"] = references.views(file);
    scene["reference_source"] = references.source(file);
    return scene;
}

json demos_json() {
    json demos = json::array();
    for (const DemoEntry& demo : demo_list()) {
        demos.push_back({{"name", std::string(demo.name)},
                         {"description", std::string(demo.description)},
                         {"scene", std::string(demo.scene)},
                         {"view", std::string(demo.view)},
                         {"controls", std::string(demo.controls)},
                         {"parameter",
                          {{"name", std::string(demo.parameter.name)},
                           {"label", std::string(demo.parameter.label)},
                           {"choices", std::vector<std::string>(demo.parameter.choices.begin(),
                                                                demo.parameter.choices.end())}}}});
    }
    return demos;
}

// A pixel's trace, as `raystep trace` prints it.
json trace_json(const ViewSession& session, const httplib::Request& request) {
    const View view = view_parameter(request);
    const int x = integer_parameter(request, "x");
    const int y = integer_parameter(request, "y");
    const PixelTrace trace = trace_pixel(session.scene_with(control_values(request)), view, x, y);
    return {{"x", x},
            {"y", y},
            {"view", std::string(view_name(view))},
            {"lines", trace.lines},
            {"stopped", trace.stopped}};
}

// The pixel against the reference, as `raystep trace --compare` shows it; or why there is no
// comparison. Apart from the trace: in the instructor's build the first comparison of a scene
// waits for raystep-reference to write its trace, and the page shows this build's trace first.
json comparison_json(const ViewSession& session, ReferenceFiles& references,
                     const httplib::Request& request) {
    const View view = view_parameter(request);
    const int x = integer_parameter(request, "x");
    const int y = integer_parameter(request, "y");
    const std::map<std::string, std::string> controls = control_values(request);
    json body{{"x", x}, {"y", y}, {"view", std::string(view_name(view))}};
    // The reference recorded the scene as its file says.
    const Scene as_written = session.scene_with({});
    if (controls_change_scene(controls, as_written)) {
        body["comparison_unavailable"] =
            "the controls change the scene; the reference's trace holds the scene as its file "
            "says: reset the controls to compare";
        return body;
    }
    try {
        const PixelComparison result = compare_pixel_with_reference(
            as_written, view, x, y, references.trace(session.scene_file()));
        json rows = json::array();
        for (const TraceRow& row : result.comparison.rows) {
            rows.push_back({{"quantity", row.quantity},
                            {"ours", row.ours},
                            {"reference", row.reference},
                            {"same", row.same}});
        }
        body["comparison"] = {{"reference_trace", result.reference_trace.string()},
                              {"notes", result.notes},
                              {"rows", rows},
                              {"first_difference", result.comparison.first_difference
                                                       ? json(*result.comparison.first_difference)
                                                       : json(nullptr)},
                              {"stopped", result.comparison.stopped},
                              {"stop", result.stop}};
    } catch (const std::exception& error) {
        // No usable reference trace (InputError), or none the reference program could write:
        // the trace above stands without its comparison.
        body["comparison_unavailable"] = error.what();
    }
    return body;
}

// The reference's image of the view (reference_files.h): the path is made from the scene and
// the view's name, never from the request.
void send_reference(const ViewSession& session, ReferenceFiles& references,
                    const httplib::Request& request, httplib::Response& response) {
    const View view = view_parameter(request);
    const std::string scene = session.scene_file();
    const std::filesystem::path path = references.image(scene, view);
    std::ifstream file(path, std::ios::binary);
    if (path.empty() || !file) {
        send_error(response, 404,
                   "no reference image of the " + std::string(view_name(view)) +
                       " view: " + reference_image_path(scene, view_name(view)).string() +
                       " is not there (a student release ships one for each view its scene "
                       "lists)");
        return;
    }
    std::ostringstream bytes;
    bytes << file.rdbuf();
    response.set_content(bytes.str(), "image/png");
}

// The demo's figure at the size the page asks for: the room it has on the screen, in the screen's
// pixels, so that a projector shows text drawn for it rather than a small figure scaled up.
void send_demo(const httplib::Request& request, httplib::Response& response) {
    const DemoEntry& demo = find_demo(request.get_param_value("name"));
    DemoSize size;
    if (request.has_param("size")) {
        try {
            size = parse_demo_size(request.get_param_value("size"));
        } catch (const std::invalid_argument& problem) {
            throw std::invalid_argument(std::string("size: ") + problem.what());
        }
    }
    // With a value of the demo's own parameter, the demo at that value alone.
    const std::string parameter(demo.parameter.name);
    const bool with_value = !parameter.empty() && request.has_param(parameter.c_str());
    const Image image =
        draw_figure(with_value ? demo.make_with(request.get_param_value(parameter.c_str()), size)
                               : demo.make(size),
                    size, find_label_font());
    LiveRender::Tile whole{{0, 0, image.width(), image.height()}, {}};
    append_display_pixels(image, whole.rect, whole.pixels);
    send_frame(
        response,
        json{{"name", std::string(demo.name)}, {"width", size.width}, {"height", size.height}},
        {whole});
}

// Answers std::invalid_argument with 400 and its message, anything else with 500: a stub's
// NotImplemented reaches the page as text, never as a dropped connection.
template <typename Handler>
httplib::Server::Handler answering(Handler handler) {
    return [handler](const httplib::Request& request, httplib::Response& response) {
        try {
            handler(request, response);
        } catch (const std::invalid_argument& error) {
            send_error(response, 400, error.what());
        } catch (const std::exception& error) {
            send_error(response, 500, error.what());
        }
    };
}

// What the page says of the program behind it, when something is wrong with it: empty when a
// rebuild will restart it as it should.
std::string program_note(const ViewServerOptions& options, const std::string& restart_failure) {
    if (options.program.empty() || !can_restart_program()) return "";
    if (!program_can_run(options.program)) {
        return options.program.string() +
               " is not there or cannot run: a build that failed to link leaves none. This page "
               "still runs the build from before, and starts the next one that links.";
    }
    return restart_failure;
}

void add_routes(httplib::Server& server, ViewSession& session, ReferenceFiles& references,
                const std::string& server_id, const ViewServerOptions& options,
                const std::string& restart_failure) {
    // The page has no icon: an empty answer, not a 404 in the browser's console.
    server.Get("/favicon.ico",
               [](const httplib::Request&, httplib::Response& response) { response.status = 204; });
    for (const PageAsset& asset : page_assets()) {
        server.Get(std::string(asset.path), [&asset](const httplib::Request&,
                                                     httplib::Response& response) {
            response.set_content(std::string(asset.text), std::string(asset.content_type));
        });
    }
    server.Get("/api/state", answering([&](const httplib::Request&, httplib::Response& response) {
                   send_json(response, {{"server", server_id},
                                        {"scene", scene_json(session, references)},
                                        {"views", view_names()},
                                        {"scenes", session.scene_list()},
                                        {"demos", demos_json()},
                                        {"program_note", program_note(options, restart_failure)}});
               }));
    server.Get("/api/open",
               answering([&](const httplib::Request& request, httplib::Response& response) {
                   session.open_listed(request.get_param_value("scene"));
                   send_json(response, scene_json(session, references));
               }));
    server.Get("/api/render",
               answering([&](const httplib::Request& request, httplib::Response& response) {
                   const std::uint64_t generation =
                       session.render({view_parameter(request), control_values(request)});
                   send_json(response, {{"generation", generation}});
               }));
    server.Get(
        "/api/tiles", answering([&](const httplib::Request& request, httplib::Response& response) {
            const LiveRender::Changes changes = session.live().changes_since(
                counter_parameter(request, "generation"), counter_parameter(request, "since"));
            send_frame(response,
                       {{"generation", changes.generation},
                        {"view", std::string(view_name(changes.view))},
                        {"controls", session.last_controls()},
                        {"scene_generation", session.scene_generation()},
                        {"state", live_render_state_name(changes.state)},
                        {"error", changes.error},
                        {"width", changes.width},
                        {"height", changes.height},
                        {"pixels_done", changes.pixels_done},
                        {"samples", changes.samples},
                        {"target_samples", changes.target_samples},
                        {"seconds", changes.seconds},
                        {"sequence", changes.sequence}},
                       changes.tiles);
        }));
    server.Get("/api/reference",
               answering([&](const httplib::Request& request, httplib::Response& response) {
                   send_reference(session, references, request, response);
               }));
    server.Get("/api/trace",
               answering([&](const httplib::Request& request, httplib::Response& response) {
                   send_json(response, trace_json(session, request));
               }));
    server.Get("/api/compare",
               answering([&](const httplib::Request& request, httplib::Response& response) {
                   send_json(response, comparison_json(session, references, request));
               }));
    server.Get("/api/demo",
               answering([](const httplib::Request& request, httplib::Response& response) {
                   send_demo(request, response);
               }));
}

// Refuses what does not come from the page on this machine: a Host header other than the
// server's own address (a DNS rebinding attack names another host), and an /api/ request without
// kApiHeader (another site's page).
httplib::Server::HandlerResponse guard(const httplib::Request& request, httplib::Response& response,
                                       int port) {
    const std::string host = request.get_header_value("Host");
    // A browser leaves out the port when it is HTTP's own, 80.
    const std::string suffix = port == 80 ? "" : ":" + std::to_string(port);
    if (host != "127.0.0.1" + suffix && host != "localhost" + suffix) {
        response.status = 403;
        response.set_content("raystep view answers only http://127.0.0.1" + suffix + "/\n",
                             "text/plain");
        return httplib::Server::HandlerResponse::Handled;
    }
    if (request.path.rfind("/api/", 0) == 0 && !request.has_header(kApiHeader)) {
        send_error(response, 403,
                   std::string("an /api/ request needs the ") + kApiHeader +
                       " header that the page sends");
        return httplib::Server::HandlerResponse::Handled;
    }
    response.set_header("Cache-Control", "no-store");
    response.set_header("X-Content-Type-Options", "nosniff");
    response.set_header("Content-Security-Policy",
                        "default-src 'self'; img-src 'self' blob: data:; style-src 'self'");
    return httplib::Server::HandlerResponse::Unhandled;
}

std::string new_server_id() {
    return std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
}

// How one round of serving ended.
enum class Served { stopped, rebuilt, port_unavailable };

// Serves the page on 127.0.0.1:`port` (0: any free port, which `port` then holds) until Ctrl-C
// or SIGTERM, or until a build has replaced the program: changed from `running`, then the same
// for a whole watch period, and runnable (program_can_run), so that neither a failed link, which
// deletes it, nor one still writing it, counts as a rebuild.
Served serve(ViewSession& session, ReferenceFiles& references, const ViewServerOptions& options,
             const FileStamps& running, const std::string& restart_failure, int& port) {
    httplib::Server server;
    // A page holds its connection open between requests; Ctrl-C waits for the last of them.
    server.set_keep_alive_timeout(1);
    // A client that sends half a request holds a worker until the read times out: more workers
    // than httplib's default of 8 and a short timeout keep a few such clients (a stuck tab, a
    // local program) from starving the page.
    server.new_task_queue = [] { return new httplib::ThreadPool(32); };
    server.set_read_timeout(2, 0);
    // One server per port. httplib's default sets SO_REUSEPORT, under which a second raystep view
    // on a taken port would share it silently rather than hear that it is taken; SO_REUSEADDR
    // alone lets a restart take its port back from connections still closing (on Windows,
    // SO_EXCLUSIVEADDRUSE is what refuses a second server).
    server.set_socket_options([](socket_t socket) {
        int yes = 1;
#if defined(_WIN32)
        setsockopt(socket, SOL_SOCKET, SO_EXCLUSIVEADDRUSE, reinterpret_cast<char*>(&yes),
                   sizeof yes);
#else
        setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
#endif
    });
    const int asked = port;
    server.set_pre_routing_handler(
        [&port](const httplib::Request& request, httplib::Response& response) {
            return guard(request, response, port);
        });
    // Lives as long as the server, whose routes hold it: a new one each round, so that the page
    // can tell a restarted server from the one before.
    const std::string server_id = new_server_id();
    add_routes(server, session, references, server_id, options, restart_failure);

    const bool bound = asked == 0 ? (port = server.bind_to_any_port("127.0.0.1")) > 0
                                  : server.bind_to_port("127.0.0.1", asked);
    if (!bound) {
        std::fprintf(stderr,
                     "raystep view: cannot listen on 127.0.0.1:%d: the port is taken (another "
                     "raystep view?) or not yours to use. Choose another with --port N, or "
                     "--port 0 for any free port.\n",
                     asked);
        return Served::port_unavailable;
    }
    std::printf("raystep view: open http://127.0.0.1:%d/ in a browser (Ctrl-C stops it)\n", port);
    std::fflush(stdout);

    // The watch loop: Ctrl-C, an edited scene, a rebuilt program.
    std::atomic<bool> rebuilt{false};
    std::atomic<bool> listening_ended{false};
    std::thread watch([&] {
        // A stop before the server listens would be lost, and it would listen on for good.
        while (!server.is_running() && !listening_ended)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        std::optional<FileStamps> settling;
        while (!listening_ended) {
            std::this_thread::sleep_for(kWatchPeriod);
            if (g_stop_signal) {
                // A reference the page asked for may be minutes from done: it is stopped too.
                references.stop();
                break;
            }
            session.reload_if_changed();
            if (!can_restart_program() || !running.changed()) {
                settling.reset();
                continue;
            }
            if (settling && !settling->changed() && program_can_run(options.program)) {
                rebuilt = true;
                break;
            }
            settling.emplace(running.files());
        }
        server.stop();
    });
    server.listen_after_bind();
    listening_ended = true;
    watch.join();
    session.live().stop();
    return rebuilt ? Served::rebuilt : Served::stopped;
}

}  // namespace

int run_view_server(const ViewServerOptions& options) {
    ViewSession session(options.project, options.threads);
    if (!options.scene.empty()) session.open(options.scene);
    ReferenceFiles references(reference_program_beside(options.program), options.reference_cache);

    g_stop_signal = 0;
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);

    int port = options.port;
    // The program as this process runs it, and why the last restart failed: after a failure the
    // page keeps this build, and waits for the next.
    FileStamps running(options.program.empty()
                           ? std::vector<std::filesystem::path>{}
                           : std::vector<std::filesystem::path>{options.program});
    std::string restart_failure;
    while (true) {
        switch (serve(session, references, options, running, restart_failure, port)) {
            case Served::stopped:
                std::printf("raystep view: stopped\n");
                return 0;
            case Served::port_unavailable:
                return kViewPortUnavailable;
            case Served::rebuilt:
                break;
        }
        std::printf("raystep view: %s was rebuilt; starting it again\n",
                    options.program.string().c_str());
        std::fflush(stdout);
        std::vector<std::string> arguments{options.program.string(), "view"};
        if (!session.scene_file().empty()) arguments.push_back(session.scene_file());
        arguments.insert(arguments.end(), {"--port", std::to_string(port)});
        if (options.threads > 0) {
            arguments.insert(arguments.end(), {"--threads", std::to_string(options.threads)});
        }
        restart_failure = "could not start " + options.program.string() +
                          " again: " + restart_program(options.program, arguments) +
                          ". This page still runs the build from before; build again to retry.";
        std::fprintf(stderr, "raystep view: %s\n", restart_failure.c_str());
        running = FileStamps(running.files());
    }
}

}  // namespace raystep
