#include "base/scene/scene_features.h"

#include <string>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "renderer/render_plan.h"

using namespace raystep;

namespace {

Scene parse(const std::string& text) {
    return parse_scene("camera 0 0 5 0 0 0 0 1 0 45\n" + text, "inline.test", RAYSTEP_TEST_DATA);
}

}  // namespace

TEST_CASE("scene_features: counts primitives by kind, mesh triangles among them", "[app]") {
    const SceneFeatures f = scene_features(
        parse("sphere 0 0 0 1\nsphere 1 0 0 1\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
              "tri 0 1 2\nmesh meshes/square.off\nplane 0 0 0 0 1 0\n"));
    CHECK(f.spheres == 2);
    CHECK(f.triangles == 3);
    CHECK(f.mesh_triangles == 2);
    CHECK(f.meshes == 1);
    CHECK(f.planes == 1);
    CHECK(f.primitives() == 6);
    CHECK_FALSE(f.uses_transforms());
    CHECK_FALSE(f.uses_lights());
    CHECK_FALSE(f.uses_reflection());
}

TEST_CASE("scene_features: transforms count only where an object uses one", "[app]") {
    CHECK_FALSE(scene_features(parse("translate 1 0 0\n")).uses_transforms());
    const SceneFeatures f =
        scene_features(parse("sphere 0 0 0 1\ntranslate 1 0 0\nsphere 0 0 0 1\n"));
    CHECK(f.transforms == 1);
    CHECK(f.transformed_objects == 1);
}

TEST_CASE("scene_features: reflection needs a specular material and maxdepth above 0", "[app]") {
    CHECK(scene_features(parse("specular 0.5 0.5 0.5\nsphere 0 0 0 1\n")).reflective_objects == 1);
    CHECK_FALSE(
        scene_features(parse("maxdepth 0\nspecular 1 1 1\nsphere 0 0 0 1\n")).uses_reflection());
    CHECK_FALSE(scene_features(parse("sphere 0 0 0 1\nspecular 1 1 1\n")).uses_reflection());
}

TEST_CASE("stages_for_view: each view runs its stages and only what the scene uses", "[app]") {
    const SceneFeatures plain = scene_features(parse("sphere 0 0 0 1\n"));
    CHECK(stages_for_view(plain, View::rays) == std::vector<int>{1, 2});
    CHECK(stages_for_view(plain, View::normal) == std::vector<int>{1, 2, 3});
    CHECK(stages_for_view(plain, View::full) == std::vector<int>{1, 2, 3, 6});
    const SceneFeatures rich = scene_features(
        parse("point 0 5 0 1 1 1\nspecular 1 1 1\ntranslate 0 1 0\nsphere 0 0 0 1\n"));
    CHECK(stages_for_view(rich, View::depth) == std::vector<int>{1, 2, 3, 5});
    CHECK(stages_for_view(rich, View::shaded) == std::vector<int>{1, 2, 3, 5, 6});
    CHECK(stages_for_view(rich, View::full) == std::vector<int>{1, 2, 3, 5, 6, 7});
}

TEST_CASE("stages_for_view: samples and quad lights add stage 8 to the views that average them",
          "[app]") {
    const SceneFeatures sampled = scene_features(parse("spp 4\nsphere 0 0 0 1\n"));
    CHECK(stages_for_view(sampled, View::full) == std::vector<int>{1, 2, 3, 6, 8});
    CHECK(stages_for_view(sampled, View::shaded) == std::vector<int>{1, 2, 3, 6, 8});
    CHECK(stages_for_view(sampled, View::depth) == std::vector<int>{1, 2, 3});
    const SceneFeatures soft =
        scene_features(parse("quadLight 0 5 0 0 0 1 1 0 0 1 1 1\nsphere 0 0 0 1\n"));
    CHECK(stages_for_view(soft, View::shaded) == std::vector<int>{1, 2, 3, 6, 8});
}

TEST_CASE("stages_for_view: transmission adds stages 7 and 9 to the full view only", "[app]") {
    const SceneFeatures glass =
        scene_features(parse("transmission 1 1 1\nior 1.5\nsphere 0 0 0 1\n"));
    CHECK(stages_for_view(glass, View::full) == std::vector<int>{1, 2, 3, 6, 7, 9});
    CHECK(stages_for_view(glass, View::shaded) == std::vector<int>{1, 2, 3, 6});
    const SceneFeatures flat =
        scene_features(parse("maxdepth 0\ntransmission 1 1 1\nsphere 0 0 0 1\n"));
    CHECK(stages_for_view(flat, View::full) == std::vector<int>{1, 2, 3, 6});
}

TEST_CASE("stages_for_view: smooth triangles add stage 11 to the views that shade", "[app]") {
    const SceneFeatures smooth = scene_features(
        parse("vertexnormal 0 0 0 0 0 1\nvertexnormal 1 0 0 0 0 1\nvertexnormal 0 1 0 0 0 1\n"
              "trinormal 0 1 2\nvertex 2 0 0\nvertex 3 0 0\nvertex 2 1 0\ntri 0 1 2\n"));
    CHECK(smooth.smooth_triangles == 1);
    CHECK(stages_for_view(smooth, View::shaded) == std::vector<int>{1, 2, 3, 6, 11});
    CHECK(stages_for_view(smooth, View::full) == std::vector<int>{1, 2, 3, 6, 11});
    CHECK(stages_for_view(smooth, View::normal) == std::vector<int>{1, 2, 3});
    const SceneFeatures plain = scene_features(parse("sphere 0 0 0 1\n"));
    CHECK(stages_for_view(plain, View::uv) == std::vector<int>{1, 2, 3, 11});
    CHECK(stages_for_view(plain, View::tangent) == std::vector<int>{1, 2, 3, 11});
}

TEST_CASE("uses_bvh: spheres under a transform stay out of the BVH", "[app]") {
    std::string ellipsoids = "scale 1 2 1\n";
    std::string spheres;
    for (std::size_t k = 0; k < kBvhFromPrimitives; ++k) {
        ellipsoids += "sphere " + std::to_string(3 * k) + " 0 0 1\n";
        spheres += "sphere " + std::to_string(3 * k) + " 0 0 1\n";
    }
    const SceneFeatures transformed = scene_features(parse(ellipsoids));
    CHECK(transformed.transformed_spheres == kBvhFromPrimitives);
    CHECK_FALSE(uses_bvh(transformed));
    CHECK(uses_bvh(scene_features(parse(spheres))));
}

TEST_CASE("scene_features: spot and area lights count as lights, area lights as sampling",
          "[app]") {
    const SceneFeatures f =
        scene_features(parse("spot 0 2 0 0 -1 0 30 1 1 1 1\n"
                             "quadLight 0 1 0 1 0 0 0 0 1 5 5 5\n"));
    CHECK(f.spot_lights == 1);
    CHECK(f.quad_lights == 1);
    CHECK(f.uses_lights());
    CHECK(f.uses_sampling());
    CHECK_FALSE(scene_features(parse("spot 0 2 0 0 -1 0 30 1 1 1 1\n")).uses_sampling());
}

TEST_CASE("scene_features: more than one sample per pixel is sampling", "[app]") {
    CHECK(scene_features(parse("spp 4\n")).samples_per_pixel == 4);
    CHECK(scene_features(parse("spp 4\n")).uses_sampling());
    CHECK_FALSE(scene_features(parse("spp 1\n")).uses_sampling());
}

TEST_CASE("scene_features: refraction needs a transmissive material and maxdepth above 0",
          "[app]") {
    const SceneFeatures f = scene_features(
        parse("sphere 0 0 0 1\ntransmission 0.9 0.9 0.9\nior 1.5\nsphere 2 0 0 1\n"));
    CHECK(f.transmissive_objects == 1);
    CHECK(f.uses_refraction());
    CHECK_FALSE(f.uses_reflection());
    CHECK_FALSE(scene_features(parse("maxdepth 0\ntransmission 1 1 1\nsphere 0 0 0 1\n"))
                    .uses_refraction());
    CHECK_FALSE(scene_features(parse("ior 1.5\nsphere 0 0 0 1\n")).uses_refraction());
}

TEST_CASE("stages_for_view: a path-traced full view runs stage 10, and stage 8 only for its spp",
          "[app]") {
    const std::string paths =
        "integrator pathtracer\ntransmission 1 1 1\nquadLight 0 5 0 0 0 1 1 0 0 1 1 1\n"
        "sphere 0 0 0 1\n";
    CHECK(stages_for_view(scene_features(parse(paths)), View::full) ==
          std::vector<int>{1, 2, 3, 6, 10});
    CHECK(scene_features(parse(paths)).transmissive_objects == 0);
    CHECK(stages_for_view(scene_features(parse("spp 4\n" + paths)), View::full) ==
          std::vector<int>{1, 2, 3, 6, 8, 10});
    // The shaded view is the direct integrator's, as in the other CSE168 integrators.
    CHECK(stages_for_view(scene_features(parse(paths)), View::shaded) ==
          std::vector<int>{1, 2, 3, 6, 8});
}
