#!/usr/bin/env python3
"""`raystep view` without a browser: what the server serves, what it refuses, and how it stops.

    view_server_test.py RAYSTEP SCENE WORK_FOLDER

Each check is a function named for the behaviour it pins down; the script runs them all and exits
1 if any failed.
"""

import os
import shutil
import sys
import time

from view_process import ViewProcess, read_ppm, rgb_of

RAYSTEP, SCENE, WORK = sys.argv[1:4]


def check_the_page_and_its_files_are_served():
    with Served([SCENE]) as view:
        for path, kind in (("/", "text/html"), ("/view.js", "text/javascript"),
                           ("/view.css", "text/css")):
            status, content_type, body = view.request(path, api_header=False)
            assert status == 200 and content_type.startswith(kind), (path, status, content_type)
            assert body, path


def check_no_file_is_served_by_its_path():
    with Served([SCENE]) as view:
        for path in ("/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/CMakeLists.txt",
                     "/scenes/stage6/cornell-box.test"):
            status, _, body = view.request(path, api_header=False)
            assert status == 404 and b"root:" not in body, (path, status)
        status, _, body = view.request("/api/open?scene=../../../etc/passwd")
        assert status == 400 and b"no scene" in body, (status, body)
        status, _, _ = view.request("/api/open?scene=/etc/passwd")
        assert status == 400, status


def check_an_api_request_without_the_page_header_is_refused():
    with Served([SCENE]) as view:
        status, _, body = view.request("/api/state", api_header=False)
        assert status == 403 and b"X-Raystep" in body, (status, body)


def check_another_host_name_is_refused():
    # A DNS-rebinding page reaches 127.0.0.1 under its own host name.
    with Served([SCENE]) as view:
        status, _, _ = view.request("/", api_header=False, host="attacker.example:%d" % view.port)
        assert status == 403, status
        status, _, _ = view.request("/", api_header=False, host="localhost:%d" % view.port)
        assert status == 200, status


def check_the_tiles_make_the_image_raystep_render_writes():
    with Served([SCENE]) as view:
        for name in ("full", "normal", "depth"):
            generation = view.json("/api/render?view=" + name)["generation"]
            header, rgba = view.wait_for_render(generation)
            written = os.path.join(WORK, "render-%s.ppm" % name)
            run([RAYSTEP, "render", SCENE, "--view", name, "-o", written])
            width, height, rgb = read_ppm(written)
            assert (width, height) == (header["width"], header["height"])
            assert rgb_of(rgba) == rgb, "the %s view differs from raystep render's" % name


def check_a_bad_control_value_is_a_message_not_a_render():
    with Served([SCENE]) as view:
        for query, words in (("spp=5&pixelsampling=jittered", b"n x n strata"),
                             ("offset=along-ray", b"needs epsilon"),
                             ("epsilon=x&offset=along-ray", b"not a number"),
                             ("view=nonsense", b"no view")):
            status, _, body = view.request("/api/render?" + query)
            assert status == 400 and words in body, (query, status, body)


def check_a_demo_is_drawn_at_the_size_the_page_asks_and_a_bad_size_is_a_message():
    # The page asks for its figure at the room it has on the screen (view.js, demoRequestSize).
    with Served([SCENE]) as view:
        header, tiles = view.frame("/api/demo?name=ray-directions&size=800x450")
        assert (header["width"], header["height"]) == (800, 450), header
        assert tiles[0][0] == (0, 0, 800, 450), tiles[0][0]
        for size, words in (("800", b"size: '800' has no 'x'"),
                            ("100x100", b"size: '100x100' is too small"),
                            ("8000x4500", b"size: '8000x4500' is too large")):
            status, _, body = view.request("/api/demo?name=ray-directions&size=" + size)
            assert status == 400 and words in body, (size, status, body)


def check_a_scene_s_own_sample_count_and_epsilon_0_are_controls_it_takes():
    # The page sends the scene's own values back: any spp a scene may ask for (up to 2^16) is
    # one the control takes; and epsilon 0 is the shadow-acne lecture's first case.
    scene = os.path.join(WORK, "many-samples.test")
    with open(scene, "w") as file:
        file.write("size 2 2\ncamera 0 0 4 0 0 0 0 1 0 45\nspp 8192\npixelsampling random\n"
                   "point 0 0 4 1 1 1\nsphere 0 0 0 1\n")
    with Served([scene]) as view:
        controls = {c["name"]: c["value"] for c in view.json("/api/state")["scene"]["controls"]}
        assert controls["spp"] == "8192", controls
        generation = view.json("/api/render?view=full&spp=8192&pixelsampling=random")
        view.wait_for_render(generation["generation"])
        generation = view.json("/api/render?view=shaded&offset=along-ray&epsilon=0")
        view.wait_for_render(generation["generation"])
        status, _, body = view.request("/api/render?view=full&spp=65537&pixelsampling=random")
        assert status == 400 and b"1 to 65536" in body, (status, body)


def check_every_page_sees_the_view_and_controls_of_the_one_render():
    # One server renders one image: a second page that asks for another view and controls
    # changes what the first page shows, and the tiles say which, so the first page's buttons
    # follow.
    with Served([SCENE]) as view:
        view.json("/api/render?view=full")
        generation = view.json("/api/render?view=normal&offset=along-ray&epsilon=0.5")
        header, _ = view.frame("/api/tiles?generation=0&since=0")
        assert header["generation"] == generation["generation"], header
        assert header["view"] == "normal", header
        assert header["controls"] == {"offset": "along-ray", "epsilon": "0.5"}, header


def check_requests_at_once_from_many_pages_neither_crash_nor_stall_it():
    # Renders started over renders, scene switches and traces, from eight clients at once, each
    # asking every path twice in turn, starting at its own place in the list.
    import threading
    with Served([SCENE]) as view:
        paths = ["/api/render?view=full", "/api/render?view=depth&spp=4",
                 "/api/open?scene=stage6/point-light.test", "/api/open?scene=stage6/cornell-box.test",
                 "/api/trace?x=3&y=3&view=shaded", "/api/compare?x=3&y=3&view=shaded",
                 "/api/tiles?generation=1&since=0"]
        failures = []

        def client(first):
            for k in range(2 * len(paths)):
                status, _, body = view.request(paths[(first + k) % len(paths)])
                if status not in (200, 400):
                    failures.append((status, body[:200]))

        clients = [threading.Thread(target=client, args=(k,)) for k in range(8)]
        for thread in clients:
            thread.start()
        for thread in clients:
            thread.join(timeout=120)
        assert not failures, failures[:3]
        assert view.process.poll() is None, "the server died"
        generation = view.json("/api/render?view=normal")["generation"]
        view.wait_for_render(generation)


def check_bytes_that_are_not_utf8_get_an_answer_not_an_empty_500():
    scene = os.path.join(WORK, "latin1.test")
    shutil.copy(SCENE, scene)
    with Served([scene]) as view:
        status, _, body = view.request("/api/render?view=%ff")
        assert status == 400 and b"no view" in body, (status, body)
        with open(scene, "ab") as file:
            file.write(b"\nsph\xe9re 0 0 0 1\n")
        error = wait_for(lambda: view.json("/api/state")["scene"].get("error"))
        assert "latin1.test:" in error and "unknown command" in error, error


def check_clients_that_send_half_a_request_do_not_starve_the_page():
    import socket
    with Served([SCENE]) as view:
        stuck = []
        for _ in range(40):
            connection = socket.create_connection(("127.0.0.1", view.port))
            connection.sendall(b"GET /api/state HTTP/1.1\r\nHost: 127.0.0")
            stuck.append(connection)
        start = time.time()
        status, _, _ = view.request("/api/state")
        waited = time.time() - start
        for connection in stuck:
            connection.close()
        assert status == 200 and waited < 10, (status, waited)


def check_a_pixel_outside_the_image_is_a_message():
    with Served([SCENE]) as view:
        status, _, body = view.request("/api/trace?x=100000&y=0&view=full")
        assert status == 400 and b"outside" in body, (status, body)


def check_an_edited_scene_renders_again():
    scene = os.path.join(WORK, "edited.test")
    shutil.copy(SCENE, scene)
    with Served([scene]) as view:
        generation = view.json("/api/render?view=full")["generation"]
        before = view.wait_for_render(generation)[1]
        text = open(scene).read()
        time.sleep(0.05)
        with open(scene, "w") as file:
            file.write(text.replace("\npoint ", "\npoint 0 1.5 0 0.2 0.2 0.2\n# was: point ", 1))
        deadline = time.time() + 30
        while view.frame("/api/tiles?generation=0&since=0")[0]["generation"] == generation:
            assert time.time() < deadline, "the edit was not noticed"
            time.sleep(0.1)
        after = view.wait_for_render(generation + 1)[1]
        assert after != before, "the edited scene rendered the same image"


def check_a_broken_edit_shows_file_and_line_and_the_fix_renders():
    scene = os.path.join(WORK, "broken.test")
    shutil.copy(SCENE, scene)
    with Served([scene]) as view:
        view.wait_for_render(view.json("/api/render?view=full")["generation"])
        good = open(scene).read()
        with open(scene, "w") as file:
            file.write(good + "\nsphere 0 0\n")
        error = wait_for(lambda: view.json("/api/state")["scene"].get("error"))
        assert "broken.test:" in error and "sphere" in error, error
        with open(scene, "w") as file:
            file.write(good)
        wait_for(lambda: "error" not in view.json("/api/state")["scene"])


def check_a_rebuilt_program_starts_again_on_the_same_port():
    program = program_copy("program")
    with Served([SCENE], program=program) as view:
        first = view.json("/api/state")["server"]
        time.sleep(0.05)
        os.utime(program)  # what a link does to it
        second = wait_for(lambda: answer_or_none(view, first))
        assert second != first
        assert view.json("/api/state")["scene"]["file"] == SCENE


def check_a_failed_link_keeps_the_server_and_the_next_link_restarts_it():
    # A link that fails deletes the program; one under way writes it before making it
    # executable. Neither is a rebuild: the page keeps the build it has, and says why.
    program = program_copy("failing-program")
    with Served([SCENE], program=program) as view:
        first = view.json("/api/state")["server"]
        os.remove(program)
        note = wait_for(lambda: view.json("/api/state")["program_note"])
        assert "not there or cannot run" in note, note
        shutil.copyfile(RAYSTEP, program)  # written, not yet executable
        time.sleep(1.5)
        state = view.json("/api/state")
        assert state["server"] == first and state["program_note"], state["program_note"]
        assert view.process.poll() is None, "the server stopped"
        os.chmod(program, 0o755)
        second = wait_for(lambda: answer_or_none(view, first))
        assert second != first
        assert view.json("/api/state")["program_note"] == ""


def check_the_instructor_build_writes_references_with_raystep_reference():
    # This build has raystep-reference beside raystep: the page gets references no release
    # shipped, written into the build tree, and the click's comparison against them.
    with Served([SCENE]) as view:
        scene = view.json("/api/state")["scene"]
        assert scene["reference_source"] == "written by raystep-reference", scene
        assert "normal" in scene["reference_views"], scene
        status, content_type, body = view.request("/api/reference?view=normal")
        assert status == 200 and content_type == "image/png", (status, body[:200])
        assert body.startswith(b"\x89PNG"), body[:8]
        compared = view.json("/api/compare?x=240&y=400&view=full")
        comparison = compared.get("comparison")
        assert comparison, compared.get("comparison_unavailable")
        assert comparison["first_difference"] is None and comparison["rows"], comparison
        # A control that changes the scene leaves the comparison out, and says why.
        compared = view.json("/api/compare?x=240&y=400&view=full&offset=along-ray&epsilon=0.001")
        assert "comparison" not in compared and "controls" in compared["comparison_unavailable"]


def check_a_trace_stands_when_the_reference_cannot_write_one():
    # A reference trace stores primitive numbers below 2^24; a scene past that gets its trace
    # and, for the comparison, the reference program's reason.
    # 257 placements of a mesh of 65,536 triangles make 16,842,752 primitives, the nearest
    # placement the last, so that the pixel's hit is numbered past 2^24. The mesh is a grid of
    # distinct triangles that its BVH separates: a pixel tests a few of each placement, not all
    # 16.8 million (which takes a minute in the sanitizer build).
    columns, rows = 256, 128
    vertices = ["%g %g 0" % (-1 + 2 * i / columns, -1 + 2 * j / rows)
                for j in range(rows + 1) for i in range(columns + 1)]
    faces = []
    for j in range(rows):
        for i in range(columns):
            a = j * (columns + 1) + i
            b, c, d = a + 1, a + columns + 1, a + columns + 2
            faces += ["3 %d %d %d" % (a, b, d), "3 %d %d %d" % (a, d, c)]
    assert len(faces) == 65536
    mesh = os.path.join(WORK, "many.off")
    with open(mesh, "w") as file:
        file.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        file.write("\n".join(vertices + faces) + "\n")
    scene = os.path.join(WORK, "many-primitives.test")
    with open(scene, "w") as file:
        file.write("size 8 8\ncamera 0 0 400 0 0 0 0 1 0 1\ndefine many many.off\n")
        for k in range(257):
            file.write("pushTransform\ntranslate 0 0 %d\ninstance many\npopTransform\n" % k)
    with Served([scene]) as view:
        trace = view.json("/api/trace?x=4&y=4&view=depth")
        assert trace["lines"][0].startswith("pixel (4, 4)"), trace["lines"][:2]
        reason = view.json("/api/compare?x=4&y=4&view=depth")["comparison_unavailable"]
        # The reference program's own message, without its output or its name twice.
        assert "2^24" in reason and "wrote" not in reason, reason
        assert reason.startswith("raystep-reference could not write the reference: primitive"), \
            reason


def check_a_taken_port_is_a_message_and_exit_code_3():
    with Served([SCENE]) as view:
        result = run([RAYSTEP, "view", SCENE, "--port", str(view.port)], expect=3)
        assert "cannot listen on 127.0.0.1:%d" % view.port in result.stderr, result.stderr


def check_a_scene_that_does_not_load_is_an_error_before_listening():
    scene = os.path.join(WORK, "bad.test")
    with open(scene, "w") as file:
        file.write("size 10 10\nsphere 1 2\n")
    result = run([RAYSTEP, "view", scene, "--port", "0"], expect=1)
    assert "bad.test:2" in result.stderr, result.stderr


def check_ctrl_c_stops_it_cleanly_mid_render():
    view = ViewProcess(RAYSTEP, [SCENE])
    view.json("/api/render?view=full&spp=64&pixelsampling=jittered")
    code, out, err = view.interrupt()
    assert code == 0 and "stopped" in out, (code, out, err)


def check_ctrl_c_while_a_slow_reference_is_written_stops_it_at_once():
    # The reference of a scene at 2^16 samples a pixel takes hours: Ctrl-C stops the server and
    # its raystep-reference within seconds, and no other reference run starts after it.
    import threading
    scene = os.path.join(WORK, "slow-reference.test")
    with open(SCENE) as source, open(scene, "w") as copy:
        copy.write(source.read() + "\nspp 65536\n")
    view = ViewProcess(RAYSTEP, [scene])
    asking = threading.Thread(target=view.request, args=("/api/compare?x=1&y=1&view=full",))
    asking.start()
    wait_for(lambda: reference_runs("slow-reference"))
    started = time.time()
    code, out, err = view.interrupt(timeout=20)
    asking.join()
    assert code == 0 and "stopped" in out, (code, out, err)
    assert time.time() - started < 10, time.time() - started
    assert not reference_runs("slow-reference"), reference_runs("slow-reference")


# ---- helpers ------------------------------------------------------------------------------------

class Served:
    def __init__(self, arguments, program=None):
        self.view = ViewProcess(program or RAYSTEP, arguments)

    def __enter__(self):
        return self.view

    def __exit__(self, *error):
        self.view.kill()


def run(command, expect=0):
    import subprocess
    result = subprocess.run(command, capture_output=True, text=True, timeout=120)
    assert result.returncode == expect, "%s exited %d, not %d: %s" % (
        " ".join(command), result.returncode, expect, result.stderr)
    return result


def wait_for(condition, timeout=30):
    deadline = time.time() + timeout
    while time.time() < deadline:
        try:
            value = condition()
        except OSError:
            value = None
        if value:
            return value
        time.sleep(0.1)
    raise AssertionError("gave up waiting after %d s" % timeout)


def program_copy(name):
    """A copy of the program in WORK/name (with the image library it loads from its own folder),
    so that "rebuilding" it touches no file of the build."""
    folder = os.path.join(WORK, name)
    os.makedirs(folder, exist_ok=True)
    program = os.path.join(folder, "raystep")
    shutil.copy2(RAYSTEP, program)
    library = os.path.join(os.path.dirname(RAYSTEP), "raystep_image_library.so")
    if os.path.exists(library):
        shutil.copy2(library, folder)
    return program


def reference_runs(name):
    """The raystep-reference processes running on a scene whose name holds `name`."""
    runs = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as file:
                words = file.read().split(b"\0")
        except OSError:
            continue
        if words and words[0].endswith(b"raystep-reference") and \
                any(name.encode() in word for word in words):
            runs.append(int(pid))
    return runs


def answer_or_none(view, old_id):
    server = view.json("/api/state")["server"]
    return server if server != old_id else None


def main():
    os.makedirs(WORK, exist_ok=True)
    checks = [value for name, value in globals().items() if name.startswith("check_")]
    failed = 0
    for check in checks:
        try:
            check()
            print("passed:", check.__name__[len("check_"):].replace("_", " "))
        except Exception as error:  # a check's failure of any kind is reported, and the rest run
            failed += 1
            print("FAILED:", check.__name__[len("check_"):].replace("_", " "), "-", repr(error))
    print("%d of %d checks failed" % (failed, len(checks)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
