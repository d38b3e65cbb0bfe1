#include "renderer/local_model.h"

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "renderer/pixel_record.h"
#include "renderer/render_pixel.h"

using namespace raystep;

namespace {

// A point on the plane z = 0 seen along `to_eye`.
SurfacePoint point_seen_from(const Vec3& to_eye) {
    const Vec3 up(0, 0, 1);
    return {Vec3(0.0), Vec3(0.0), up, up, glm::normalize(to_eye)};
}

Material phong(const Color& diffuse, const Color& specular, double shininess) {
    Material material;
    material.diffuse = diffuse;
    material.specular = specular;
    material.shininess = shininess;
    return material;
}

}  // namespace

TEST_CASE("phong_lobe_term: a diffuse surface is lit as stage 6 lights it", "[app]") {
    const Material matte = phong(Color(0.5, 0.25, 0.125), Color(0.0), 0.0);
    const SurfacePoint point = point_seen_from(Vec3(1, 0, 2));
    const LightSample light{glm::normalize(Vec3(-1, 1, 1)), 2.0, Color(2.0)};
    CHECK(phong_lobe_term(matte, point, light) == blinn_phong(matte, point, light));
}

TEST_CASE("phong_lobe_term: at the mirror direction the lobe is Ks (s + 2) / 2 times the cosine",
          "[app]") {
    const Material shiny = phong(Color(0.0), Color(1.0), 10.0);
    const SurfacePoint point = point_seen_from(Vec3(1, 0, 1));
    const LightSample mirror{glm::normalize(Vec3(-1, 0, 1)), 1.0, Color(1.0)};
    CHECK(phong_lobe_term(shiny, point, mirror).r == Approx(6.0 / std::sqrt(2.0)));
    // The same light seen from above: R is the normal, 45 degrees off L, so cos(45)^10 of it.
    const SurfacePoint above = point_seen_from(Vec3(0, 0, 1));
    CHECK(phong_lobe_term(shiny, above, mirror).r ==
          Approx(6.0 / std::sqrt(2.0) * std::pow(std::sqrt(0.5), 10.0)));
    // Behind the surface: nothing, the lobe neither.
    const LightSample below{glm::normalize(Vec3(-1, 0, -1)), 1.0, Color(1.0)};
    CHECK(phong_lobe_term(shiny, point, below) == Color(0.0));
}

TEST_CASE("phong_lobe_term: seen from the normal, the lobe reflects exactly Ks of a uniform sky",
          "[app]") {
    // The (s + 2) / (2 pi) normalisation: the integral over the hemisphere of f cos(theta) is Ks
    // at normal incidence. The term is pi f cos(theta) for a light of intensity 1, so the
    // midpoint rule over (theta, phi) of term sin(theta) / pi must give Ks.
    for (const double shininess : {1.0, 10.0, 100.0}) {
        CAPTURE(shininess);
        const Material shiny = phong(Color(0.0), Color(0.7), shininess);
        const SurfacePoint point = point_seen_from(Vec3(0, 0, 1));
        const int steps = 2000;
        const double d_theta = glm::pi<double>() / 2.0 / steps;
        double reflected = 0.0;
        for (int k = 0; k < steps; ++k) {
            const double theta = (k + 0.5) * d_theta;
            const LightSample light{Vec3(std::sin(theta), 0, std::cos(theta)), 1.0, Color(1.0)};
            // The lobe is symmetric about the normal here: phi integrates to 2 pi.
            reflected += phong_lobe_term(shiny, point, light).r * std::sin(theta) * d_theta;
        }
        CHECK(reflected * 2.0 * glm::pi<double>() / glm::pi<double>() == Approx(0.7).epsilon(1e-4));
    }
}

TEST_CASE("local_colour: CSE167's is stage 6's local_shading, CSE168's sums the Phong lobes",
          "[app]") {
    Material material = phong(Color(0.5), Color(0.3), 20.0);
    material.ambient = Color(0.1);
    material.emission = Color(0.05);
    const SurfacePoint point = point_seen_from(Vec3(1, 0, 1));
    const std::vector<LightSample> lights = {{glm::normalize(Vec3(-1, 0, 1)), 1.0, Color(1.0)},
                                             {glm::normalize(Vec3(0, 1, 1)), 1.0, Color(0.5)}};
    CHECK(local_colour(SceneDialect::cse167, material, point, lights) ==
          local_shading(material, point, lights));
    const Color expected = Color(0.15) + phong_lobe_term(material, point, lights[0]) +
                           phong_lobe_term(material, point, lights[1]);
    const Color cse168 = local_colour(SceneDialect::cse168, material, point, lights);
    CHECK(cse168.r == Approx(expected.r));
    CHECK(cse168.r > local_shading(material, point, lights).r);  // the lobe is brighter at R
}

TEST_CASE("PixelRecorder: a light's recorded term is the dialect's, the one the pixel sums",
          "[app]") {
    // One point light and nothing else to add, so the local colour is that light's term.
    const std::string text =
        "size 1 1\ncamera 0 3 3 0 0 0 0 1 0 20\nambient 0 0 0\ndiffuse 0.2 0.2 0.2\n"
        "specular 0.5 0.5 0.5\nshininess 10\npoint -1 3 -3 1 1 1\nplane 0 0 0 0 1 0\n";
    std::vector<Color> terms;
    for (const std::string& dialect : {std::string(), std::string("integrator direct\n")}) {
        const Scene scene = parse_scene(text + dialect, "record.test", ".");
        PixelRecord record;
        PixelRecorder recorder(record, scene.dialect);
        render_pixel(prepare_render_scene(scene), View::shaded, 0, 0, recorder);
        REQUIRE(record.lights.size() == 1);
        REQUIRE(record.local);
        CHECK(*record.local == record.lights[0].term);
        terms.push_back(record.lights[0].term);
    }
    CHECK(terms[0] != terms[1]);
}
