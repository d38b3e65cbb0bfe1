#include "app/cli/info_command.h"

#include <chrono>
#include <cstdio>

#include "app/render/render_plan.h"
#include "base/math/to_text.h"
#include "base/scene/scene_features.h"
#include "base/scene/scene_loader.h"

namespace raystep {

namespace {

std::string counted(std::size_t n, const std::string& singular, const std::string& plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

std::string stage_list(const std::vector<int>& stages) {
    std::string text;
    for (const int stage : stages)
        text += (text.empty() ? "" : " ") + std::to_string(stage);
    return text;
}

void row(const char* label, const std::string& value) {
    std::printf("%-11s %s\n", label, value.c_str());
}

}  // namespace

CLI::App* add_info_command(CLI::App& app, InfoArguments& arguments) {
    CLI::App* command =
        app.add_subcommand("info", "Show what a scene uses and which stages render it");
    command->add_option("scene", arguments.scene, "Scene file")
        ->required()
        ->check(CLI::ExistingFile);
    return command;
}

int run_info(const InfoArguments& arguments) {
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = load_scene(arguments.scene);
    const double load_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const SceneFeatures f = scene_features(scene);
    const CameraSpec& camera = scene.camera;

    row("scene", scene.path + " (loaded in " + to_text(load_seconds) + " s)");
    row("image", std::to_string(scene.width) + " x " + std::to_string(scene.height) +
                     ", maxdepth " + std::to_string(scene.max_depth) +
                     (scene.output.empty() ? "" : ", output " + scene.output));
    std::string projection = camera.ortho ? "orthographic over [" + to_text(camera.ortho->left) +
                                                ", " + to_text(camera.ortho->right) + "] x [" +
                                                to_text(camera.ortho->bottom) + ", " +
                                                to_text(camera.ortho->top) + "]"
                                          : "perspective, fovy " + to_text(camera.fovy_degrees);
    row("camera", projection + ", from " + to_text(camera.lookfrom) + " to " +
                      to_text(camera.lookat) + ", up " + to_text(camera.up));
    row("primitives", counted(f.primitives(), "primitive", "primitives") + ": " +
                          counted(f.spheres, "sphere", "spheres") + ", " +
                          counted(f.triangles, "triangle", "triangles") + ", " +
                          counted(f.planes, "plane", "planes"));
    row("meshes", f.meshes == 0 ? "none"
                                : counted(f.meshes, "mesh", "meshes") + " with " +
                                      counted(f.mesh_triangles, "triangle", "triangles"));
    if (f.mesh_definitions > 0) {
        row("defined meshes", counted(f.mesh_definitions, "definition", "definitions") +
                                  ", placed by " +
                                  counted(f.mesh_instances, "instance", "instances") + ": " +
                                  counted(f.instanced_triangles, "triangle", "triangles") +
                                  " in the image, each definition's kept once");
    }
    row("transforms", f.uses_transforms()
                          ? counted(f.transformed_objects, "object", "objects") + " under " +
                                counted(f.transforms, "transform", "transforms")
                          : "none");
    row("lights", f.uses_lights()
                      ? counted(f.point_lights, "point light", "point lights") + ", " +
                            counted(f.directional_lights, "directional light", "directional lights")
                      : "none (ambient and emission only, no shadow rays)");
    row("reflection", f.uses_reflection()
                          ? counted(f.reflective_objects, "mirror object", "mirror objects") +
                                ", up to " + std::to_string(scene.max_depth) + " bounces"
                          : "none");
    const std::size_t bounded = bvh_primitives(f);
    row("structure", uses_bvh(f)
                         ? "a BVH (SAH) over the " + std::to_string(bounded) +
                               " spheres and triangles without a transform (from " +
                               std::to_string(kBvhFromPrimitives) +
                               " on; docs/stage4.md, \"When a structure pays\")"
                         : "none over the " +
                               counted(bounded, "sphere or triangle", "spheres and triangles") +
                               " without a transform, tested one by one (a BVH from " +
                               std::to_string(kBvhFromPrimitives) + " on)" +
                               (f.instances > 0 ? "; the instances, below, have their own" : ""));
    if (f.instances > 0) {
        row("instances",
            counted(f.instances, "instance", "instances") +
                ", each intersected in its own frame (docs/scene-format.md, \"Instances\"): " +
                (f.instances >= kBvhFromPrimitives ? "under a BVH of their world boxes"
                                                   : "tested one by one") +
                "; the largest holds " +
                counted(f.largest_instance, "sphere or triangle", "spheres and triangles") +
                (f.largest_instance >= kBvhFromPrimitives ? ", under a BVH of its own" : ""));
    }
    row("ray offset",
        std::string(offset_rule_name(scene.ray_offset.rule)) +
            (uses_epsilon(scene.ray_offset.rule) ? ", epsilon " + to_text(scene.ray_offset.epsilon)
                                                 : " (no epsilon to tune)"));
    row("stages", "full image " + stage_list(stages_for_view(f, View::full)) + "; shaded view " +
                      stage_list(stages_for_view(f, View::shaded)) +
                      "; depth, normal and barycentric views " +
                      stage_list(stages_for_view(f, View::normal)) + "; rays view " +
                      stage_list(stages_for_view(f, View::rays)));
    return 0;
}

}  // namespace raystep
