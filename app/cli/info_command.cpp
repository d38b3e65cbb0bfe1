#include "app/cli/info_command.h"

#include <chrono>
#include <cstdio>

#include "base/math/to_text.h"
#include "base/scene/scene_features.h"
#include "base/scene/scene_loader.h"
#include "renderer/render_plan.h"

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

std::string lights_row(const SceneFeatures& f) {
    if (!f.uses_lights()) return "none (ambient and emission only, no shadow rays)";
    std::string text = counted(f.point_lights, "point light", "point lights") + ", " +
                       counted(f.directional_lights, "directional light", "directional lights");
    if (f.spot_lights > 0) text += ", " + counted(f.spot_lights, "spot light", "spot lights");
    if (f.quad_lights > 0) {
        text += ", " + counted(f.quad_lights, "area light", "area lights") + " (quadLight)";
    }
    return text;
}

// Samples per pixel and per area light, and the seed they come from.
std::string sampling_row(const Scene& scene, const SceneFeatures& f) {
    std::string text = counted(static_cast<std::size_t>(scene.samples_per_pixel),
                               "sample per pixel", "samples per pixel");
    if (scene.samples_per_pixel > 1)
        text += ", " + std::string(sample_pattern_name(scene.pixel_sampling));
    if (f.path_traced) {
        const char* const sampling[] = {"uniform over the hemisphere", "cosine-weighted",
                                        "by the BRDF"};
        const char* const next_event[] = {"off", "on", "by MIS"};
        text += "; paths (integrator pathtracer) of " +
                (scene.max_depth == kUnboundedDepth
                     ? std::string("any length")
                     : "at most " + std::to_string(scene.max_depth) + " bounces") +
                (scene.russian_roulette ? ", ended by Russian roulette" : "") +
                ", directions drawn " + sampling[static_cast<int>(scene.importance_sampling)] +
                ", next event estimation " + next_event[static_cast<int>(scene.next_event)];
    } else if (f.quad_lights > 0 && scene.integrator == Integrator::analyticdirect) {
        text += "; area lights integrated exactly (integrator analyticdirect)";
    } else if (f.quad_lights > 0) {
        text += "; " + counted(static_cast<std::size_t>(scene.light_samples), "sample", "samples") +
                " per area light, " + (scene.light_stratify ? "stratified" : "random");
    }
    return text + "; seed " + std::to_string(scene.seed);
}

// The bounces a mirror or a dielectric follows: maxdepth, or with no limit the default depth.
std::string bounces_text(const Scene& scene) {
    const int depth = scene.max_depth == kUnboundedDepth ? kDefaultDepth : scene.max_depth;
    return "up to " + std::to_string(depth) + " bounces";
}

std::string refraction_row(const Scene& scene, const SceneFeatures& f) {
    if (!f.uses_refraction()) return "none";
    return counted(f.transmissive_objects, "dielectric object", "dielectric objects") +
           ", Fresnel " + (scene.schlick_fresnel ? "by Schlick's approximation" : "exact") + ", " +
           bounces_text(scene);
}

std::string dialect_row(const Scene& scene) {
    if (scene.dialect == SceneDialect::cse167) return "CSE167, the ray tracer's";
    return "CSE168, the path tracer's (its 'integrator'): no ambient unless written, specular a "
           "glossy lobe with no mirror ray, quad lights drawn";
}

// The commands read with no effect or rendered otherwise, each with its line; the warnings that
// say what raystep does with each go to the error stream.
std::string notes_row(const Scene& scene) {
    std::string text;
    for (const SceneNote& note : scene.notes)
        text +=
            (text.empty() ? "" : ", ") + note.command + " (line " + std::to_string(note.line) + ")";
    return text + ": each has no effect or renders otherwise; the warnings say how";
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
    for (const SceneNote& note : scene.notes)
        std::fprintf(stderr, "%s\n", warning_text(scene, note).c_str());

    row("scene", scene.path + " (loaded in " + to_text(load_seconds) + " s)");
    row("dialect", dialect_row(scene));
    row("image",
        std::to_string(scene.width) + " x " + std::to_string(scene.height) + ", maxdepth " +
            (scene.max_depth == kUnboundedDepth ? "-1 (no limit)"
                                                : std::to_string(scene.max_depth)) +
            (scene.output.empty() ? "" : ", output " + scene.output) +
            (scene.background == Color(0.0) ? "" : ", background " + to_text(scene.background)));
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
    if (f.uses_smooth_normals()) {
        row("normals", counted(f.smooth_triangles, "triangle", "triangles") +
                           " shaded smooth by their vertex normals (stage 11)");
    }
    if (f.mapped_objects > 0) {
        row("maps", counted(f.mapped_objects, "object", "objects") +
                        " with a texture, normal map " + "or bump map, over " +
                        counted(scene.textures.size(), "image", "images") + " (stage 11)");
    }
    row("transforms", f.uses_transforms()
                          ? counted(f.transformed_objects, "object", "objects") + " under " +
                                counted(f.transforms, "transform", "transforms")
                          : "none");
    row("lights", lights_row(f));
    if (f.uses_sampling()) row("sampling", sampling_row(scene, f));
    row("reflection", f.uses_reflection()
                          ? counted(f.reflective_objects, "mirror object", "mirror objects") +
                                ", " + bounces_text(scene)
                          : "none");
    row("refraction", refraction_row(scene, f));
    if (!scene.notes.empty()) row("warnings", notes_row(scene));
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
