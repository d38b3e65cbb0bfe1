"""Render a path-traced raystep scene in Blender's Cycles, for docs/measurements/cycles.md.

Run by Blender, not by python3:

    blender -b --factory-startup --python scripts/cycles-render.py -- SCENE OUT.exr SPP SEED THREADS

It reads the commands a diffuse CSE168 scene such as scenes/stage10/cornell-box.test uses (size,
camera, vertex, tri, diffuse, emission, quadLight, maxdepth) and refuses any other that would
change the image, so that what Cycles renders is the scene raystep renders. The conventions are
matched, each for a stated reason:

- a `diffuse` Kd is a Diffuse BSDF of colour Kd (Lambert, albedo Kd, as stage 10's Kd / pi);
- a quad light is a two-triangle mesh with an Emission shader of strength 1 and colour L (Cycles'
  mesh emission is radiance L), emitting on its ac x ab side only: its back is black, as raystep's
  seen_quad_light is from behind;
- the camera looks as raystep's does: from the eye to the centre, fovy vertical, one pixel a box
  filter of one pixel (raystep averages samples spread over the pixel's square);
- no clamping, no denoising, no adaptive sampling, no light threshold, and bounces up to 1024
  (raystep's `maxdepth -1` is unbounded, ended by Russian roulette): Cycles' estimate is then
  unbiased, as raystep's is;
- the output is linear EXR (no view transform), as `raystep render -o X.exr` writes.

It prints `render_seconds S`: the render alone, without Blender's start-up and the scene's loading.
"""

import math
import sys
import time

import bpy
import mathutils


def fail(path, line, problem):
    sys.stderr.write(f"{path}:{line}: {problem}\n")
    sys.exit(2)


def read_scene(path):
    scene = {"vertices": [], "triangles": [], "lights": [], "size": (160, 120), "camera": None}
    diffuse = (0.0, 0.0, 0.0)
    emission = (0.0, 0.0, 0.0)
    # Commands that change nothing under the scene's own integrator, or that only raystep reads.
    ignored = {"output", "integrator", "spp", "seed", "maxverts", "ambient", "specular",
               "shininess", "russianroulette", "nexteventestimation", "importancesampling",
               "lightsamples", "lightstratify", "gamma"}
    with open(path) as f:
        for number, raw in enumerate(f, 1):
            words = raw.split("#")[0].split()
            if not words:
                continue
            command, args = words[0], words[1:]
            if command == "size":
                scene["size"] = (int(args[0]), int(args[1]))
            elif command == "camera":
                scene["camera"] = [float(a) for a in args]
            elif command == "vertex":
                scene["vertices"].append(tuple(float(a) for a in args))
            elif command == "tri":
                scene["triangles"].append((tuple(int(a) for a in args), diffuse, emission))
            elif command == "diffuse":
                diffuse = tuple(float(a) for a in args)
            elif command == "emission":
                emission = tuple(float(a) for a in args)
            elif command == "quadLight":
                values = [float(a) for a in args]
                scene["lights"].append((values[0:3], values[3:6], values[6:9], values[9:12]))
            elif command == "maxdepth" and args[0] != "-1":
                fail(path, number, "only maxdepth -1 (unbounded) is matched in Cycles")
            elif command == "maxdepth":
                continue
            elif command == "brdf" and args[0] != "phong":
                fail(path, number, "only diffuse surfaces are matched in Cycles")
            elif command == "brdf":
                continue
            elif command in ignored:
                if command == "specular" and any(float(a) != 0 for a in args):
                    fail(path, number, "a specular lobe is not matched in Cycles")
                continue
            else:
                fail(path, number, f"'{command}' is not matched in Cycles")
    if scene["camera"] is None:
        fail(path, 1, "no camera")
    return scene


def material(name, colour, emission, one_sided=False):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if any(c > 0 for c in emission):
        emit = nodes.new("ShaderNodeEmission")
        emit.inputs["Color"].default_value = (*emission, 1.0)
        emit.inputs["Strength"].default_value = 1.0
        if one_sided:
            # Black behind: mix with a black emission by the geometry's backfacing flag.
            black = nodes.new("ShaderNodeEmission")
            black.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
            geometry = nodes.new("ShaderNodeNewGeometry")
            mix = nodes.new("ShaderNodeMixShader")
            links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
            links.new(emit.outputs["Emission"], mix.inputs[1])
            links.new(black.outputs["Emission"], mix.inputs[2])
            links.new(mix.outputs["Shader"], out.inputs["Surface"])
        else:
            links.new(emit.outputs["Emission"], out.inputs["Surface"])
        return m
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (*colour, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return m


def add_mesh(name, vertices, faces, mat):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    obj.data.materials.append(mat)
    bpy.context.scene.collection.objects.link(obj)


def build(scene):
    by_material = {}
    for (a, b, c), kd, le in scene["triangles"]:
        by_material.setdefault((kd, le), []).append((a, b, c))
    for k, ((kd, le), faces) in enumerate(by_material.items()):
        add_mesh(f"surface{k}", scene["vertices"], faces, material(f"m{k}", kd, le))
    for k, (corner, ab, ac, radiance) in enumerate(scene["lights"]):
        a = mathutils.Vector(corner)
        b, c = a + mathutils.Vector(ab), a + mathutils.Vector(ac)
        d = b + mathutils.Vector(ac)
        # Faces wound a, c, d, b: Blender's front is their normal, ac x ab, the emitting side.
        add_mesh(f"light{k}", [a, b, c, d], [(0, 2, 3, 1)],
                 material(f"light{k}", (0, 0, 0), tuple(radiance), one_sided=True))

    eye = mathutils.Vector(scene["camera"][0:3])
    centre = mathutils.Vector(scene["camera"][3:6])
    up = mathutils.Vector(scene["camera"][6:9])
    fovy = scene["camera"][9]
    w = (eye - centre).normalized()
    u = up.cross(w).normalized()
    v = w.cross(u)
    camera_data = bpy.data.cameras.new("camera")
    camera_data.sensor_fit = "VERTICAL"
    camera_data.angle_y = math.radians(fovy)
    camera_data.clip_start = 1e-4
    camera_data.clip_end = 1e4
    camera = bpy.data.objects.new("camera", camera_data)
    # Blender's camera looks along its -z with y up: its axes are u, v, w.
    camera.matrix_world = mathutils.Matrix(
        ((u.x, v.x, w.x, eye.x), (u.y, v.y, w.y, eye.y), (u.z, v.z, w.z, eye.z), (0, 0, 0, 1)))
    bpy.context.scene.collection.objects.link(camera)
    bpy.context.scene.camera = camera


def assign(owner, name, value):
    """owner.name = value, refusing a name the owner does not have: a bpy struct takes any
    attribute silently, and a misspelt setting would leave Cycles' default in force."""
    if not hasattr(owner, name):
        sys.stderr.write(f"Blender {bpy.app.version_string} has no setting {name}\n")
        sys.exit(2)
    setattr(owner, name, value)


def settings(width, height, spp, seed, threads):
    s = bpy.context.scene
    s.render.engine = "CYCLES"
    for name, value in (
            ("device", "CPU"), ("samples", spp), ("seed", seed),
            ("use_adaptive_sampling", False), ("use_denoising", False),
            ("sample_clamp_direct", 0.0), ("sample_clamp_indirect", 0.0),
            ("light_sampling_threshold", 0.0), ("max_bounces", 1024), ("diffuse_bounces", 1024),
            ("glossy_bounces", 0), ("transmission_bounces", 0), ("volume_bounces", 0),
            ("transparent_max_bounces", 0), ("caustics_reflective", True),
            ("pixel_filter_type", "BOX"), ("filter_width", 1.0)):
        assign(s.cycles, name, value)
    for name, value in (("threads_mode", "FIXED"), ("threads", threads), ("resolution_x", width),
                        ("resolution_y", height), ("resolution_percentage", 100),
                        ("film_transparent", False)):
        assign(s.render, name, value)
    s.world = bpy.data.worlds.new("black")
    s.world.use_nodes = True
    s.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    assign(s.view_settings, "view_transform", "Standard")
    assign(s.view_settings, "look", "None")
    for name, value in (("file_format", "OPEN_EXR"), ("color_depth", "32"), ("exr_codec", "ZIP")):
        assign(s.render.image_settings, name, value)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    if len(argv) != 5:
        sys.stderr.write("usage: blender -b --factory-startup --python cycles-render.py -- "
                         "SCENE OUT.exr SPP SEED THREADS\n")
        sys.exit(2)
    path, output, spp, seed, threads = argv[0], argv[1], int(argv[2]), int(argv[3]), int(argv[4])
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    scene = read_scene(path)
    build(scene)
    settings(*scene["size"], spp, seed, threads)
    bpy.context.scene.render.filepath = output
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    print(f"render_seconds {time.perf_counter() - start:.3f}")


main()
