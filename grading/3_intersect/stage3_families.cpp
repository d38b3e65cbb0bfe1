#include "grading/3_intersect/stage3_families.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <glm/geometric.hpp>

#include "grading/3_intersect/closed_mesh.h"

namespace raystep {

namespace {

// Helpers

Vec3 on_triangle(const Triangle& tri, double beta, double gamma) {
    return tri.p0 + beta * (tri.p1 - tri.p0) + gamma * (tri.p2 - tri.p0);
}

// A ray from `origin` through `target`, with the direction scaled by a random factor so that t is
// rarely a distance (the contract does not need unit directions).
Ray ray_through(PortableRandom& random, const Vec3& origin, const Vec3& target) {
    return {origin, (target - origin) * random.decade(-1.0, 1.0)};
}

RayCase single(const Ray& ray, const CaseShape& shape) {
    RayCase ray_case;
    ray_case.ray = ray;
    ray_case.primitives.push_back({shape, {}});
    return ray_case;
}

// Any unit vector perpendicular to v.
Vec3 perpendicular(PortableRandom& random, const Vec3& v) {
    return glm::normalize(glm::cross(v, random.unit_vector()));
}

// A random rotation: a uniform unit quaternion turned into a matrix (Shoemake 1992).
glm::dmat3 random_rotation(PortableRandom& random) {
    const double u1 = random.unit();
    const double u2 = random.uniform(0.0, 2.0 * 3.14159265358979323846);
    const double u3 = random.uniform(0.0, 2.0 * 3.14159265358979323846);
    const double a = std::sqrt(1.0 - u1);
    const double b = std::sqrt(u1);
    const double x = a * std::sin(u2), y = a * std::cos(u2), z = b * std::sin(u3),
                 w = b * std::cos(u3);
    return {{1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)},
            {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)},
            {2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)}};
}

// Random triangles, spheres and planes, and rays aimed near them.

RayCase random_triangle(PortableRandom& random) {
    const Triangle tri{random.point(2.0), random.point(2.0), random.point(2.0)};
    const Vec3 target = on_triangle(tri, random.uniform(-0.2, 1.2), random.uniform(-0.2, 1.2));
    RayCase ray_case = single(
        ray_through(random, target + random.unit_vector() * random.uniform(3.0, 12.0), target),
        tri);
    // One case in five with a t_max that may fall short of the triangle.
    if (random.unit() < 0.2)
        ray_case.ray.t_max = random.uniform(0.5, 2.0) * glm::length(target - ray_case.ray.origin) /
                             glm::length(ray_case.ray.direction);
    return ray_case;
}

RayCase random_sphere(PortableRandom& random) {
    const Sphere sphere{random.point(2.0), random.uniform(0.1, 3.0)};
    const Vec3 target = sphere.center + random.point(1.2 * sphere.radius);
    // One ray in ten starts inside.
    const Vec3 origin =
        random.unit() < 0.1
            ? sphere.center + random.point(0.5 * sphere.radius)
            : sphere.center + random.unit_vector() * (sphere.radius + random.uniform(1.0, 10.0));
    return single(ray_through(random, origin, target), sphere);
}

RayCase random_plane(PortableRandom& random) {
    const Plane plane{random.point(2.0), random.unit_vector() * random.decade(-1.0, 1.0)};
    return single(ray_through(random, random.point(10.0), random.point(3.0)), plane);
}

// The watertight families: rays aimed exactly at an edge or a vertex that triangles of a closed
// mesh share, the mesh placed near the origin or 1e5 to 1e6 away. Each vertex is placed once,
// so the triangles that share it share its coordinates bit for bit, as in a real mesh.

const ClosedMesh& shared_mesh() {
    static const ClosedMesh mesh = icosphere(2);
    return mesh;
}

struct Placement {
    glm::dmat3 rotation;
    double scale;
    Vec3 offset;

    Vec3 operator()(const Vec3& v) const { return offset + scale * (rotation * v); }
};

Placement place(PortableRandom& random, bool far) {
    return {random_rotation(random), random.uniform(0.5, 2.0),
            far ? random.unit_vector() * random.uniform(1e5, 1e6) : random.point(2.0)};
}

RayCase aimed_at_mesh(PortableRandom& random, const Placement& placement, const Vec3& target,
                      const std::vector<std::uint32_t>& faces) {
    const ClosedMesh& mesh = shared_mesh();
    std::map<std::uint32_t, Vec3> placed;
    const auto vertex = [&](std::uint32_t v) {
        const auto found = placed.find(v);
        if (found != placed.end()) return found->second;
        return placed[v] = placement(mesh.vertices[v]);
    };
    RayCase ray_case;
    const Vec3 origin =
        placement.offset + random.unit_vector() * placement.scale * random.uniform(1.5, 5.0);
    ray_case.ray = ray_through(random, origin, target);
    for (const std::uint32_t f : faces) {
        const auto& [a, b, c] = mesh.faces[f];
        ray_case.primitives.push_back({Triangle{vertex(a), vertex(b), vertex(c)}, {}});
    }
    // The group covers a neighbourhood of the aim point only when every triangle faces the ray
    // from the same side. On the silhouette the triangles overlap on one side of the shared edge
    // or vertex, and a ray grazing it may miss them all: no watertight promise there. The facing
    // is decided in doubles with a wide margin, so the exact sign is the same.
    int front = 0;
    int back = 0;
    for (const CasePrimitive& primitive : ray_case.primitives) {
        const Triangle& t = std::get<Triangle>(primitive.shape);
        const Vec3 n = glm::cross(t.p1 - t.p0, t.p2 - t.p0);
        const double facing = glm::dot(ray_case.ray.direction, n);
        const double margin = 1e-6 * glm::length(ray_case.ray.direction) * glm::length(n);
        front += facing < -margin;
        back += facing > margin;
    }
    const int count = static_cast<int>(ray_case.primitives.size());
    ray_case.watertight = front == count || back == count;
    return ray_case;
}

RayCase shared_edge(PortableRandom& random, bool far) {
    const ClosedMesh& mesh = shared_mesh();
    const ClosedMesh::Edge& edge = mesh.edges[static_cast<std::size_t>(
        random.integer(0, static_cast<std::int64_t>(mesh.edges.size()) - 1))];
    const Placement placement = place(random, far);
    const Vec3 a = placement(mesh.vertices[edge.a]);
    const Vec3 b = placement(mesh.vertices[edge.b]);
    const Vec3 target = a + random.uniform(0.02, 0.98) * (b - a);
    return aimed_at_mesh(random, placement, target, {edge.faces[0], edge.faces[1]});
}

RayCase shared_vertex(PortableRandom& random, bool far) {
    const ClosedMesh& mesh = shared_mesh();
    const auto v = static_cast<std::uint32_t>(
        random.integer(0, static_cast<std::int64_t>(mesh.vertices.size()) - 1));
    const Placement placement = place(random, far);
    return aimed_at_mesh(random, placement, placement(mesh.vertices[v]), mesh.vertex_faces[v]);
}

RayCase shared_edge_near(PortableRandom& random) {
    return shared_edge(random, false);
}
RayCase shared_edge_far(PortableRandom& random) {
    return shared_edge(random, true);
}
RayCase shared_vertex_near(PortableRandom& random) {
    return shared_vertex(random, false);
}
RayCase shared_vertex_far(PortableRandom& random) {
    return shared_vertex(random, true);
}

// Rays at a grazing angle to the triangle, 1e-2 to 1e-12 radians, through it or near it.
RayCase grazing(PortableRandom& random) {
    const Triangle tri{random.point(2.0), random.point(2.0), random.point(2.0)};
    const Vec3 n = glm::normalize(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
    const Vec3 target = on_triangle(tri, random.uniform(-0.1, 1.0), random.uniform(-0.1, 1.0));
    const double angle = random.decade(-12.0, -2.0) * (random.unit() < 0.5 ? -1.0 : 1.0);
    const Vec3 along = perpendicular(random, n);
    const Vec3 direction = glm::normalize(along + std::tan(angle) * n);
    return single(ray_through(random, target - direction * random.uniform(1.0, 10.0), target), tri);
}

// Rays exactly in the triangle's plane: the triangle lies in a plane x, y or z = c and the ray
// keeps that coordinate c with a zero component, so it is in the plane bit for bit. A miss, by
// the contract, for every correct test.
RayCase in_plane(PortableRandom& random) {
    const int axis = static_cast<int>(random.integer(0, 2));
    const double c = random.uniform(-2.0, 2.0);
    const auto planar = [&](Vec3 p) {
        p[axis] = c;
        return p;
    };
    const Triangle tri{planar(random.point(2.0)), planar(random.point(2.0)),
                       planar(random.point(2.0))};
    const Vec3 target = on_triangle(tri, random.uniform(-0.2, 1.2), random.uniform(-0.2, 1.2));
    Vec3 origin = planar(random.point(6.0));
    Ray ray{origin, target - origin};
    ray.direction[axis] = 0.0;
    return single(ray, tri);
}

// Slivers, nearly degenerate: the third vertex 1e-15 to 1e-3 of the edge's length off the line
// through the first two. One in five is exactly degenerate: integer vertices on one line, or
// a repeated vertex. Of the rest, about one in seven has its third vertex one ulp off the line
// through the other two, in one coordinate: the exact normal is not zero, yet the double cross
// product's two nearly equal products often round to the same double, and it is.
RayCase sliver(PortableRandom& random) {
    Triangle tri;
    if (random.unit() < 0.2) {
        const Vec3 p0{static_cast<double>(random.integer(-5, 5)),
                      static_cast<double>(random.integer(-5, 5)),
                      static_cast<double>(random.integer(-5, 5))};
        const Vec3 step{static_cast<double>(random.integer(-3, 3)),
                        static_cast<double>(random.integer(-3, 3)),
                        static_cast<double>(random.integer(1, 3))};
        tri = random.unit() < 0.5 ? Triangle{p0, p0 + step, p0 + 3.0 * step}
                                  : Triangle{p0, p0 + step, p0};
    } else if (random.unit() < 0.15) {
        const Vec3 p0 = random.point(2.0);
        const Vec3 step = random.point(1.0);
        Vec3 p2 = p0 + 2.0 * step;
        const auto axis = static_cast<int>(random.integer(0, 2));
        p2[axis] = std::nextafter(p2[axis], random.unit() < 0.5 ? -HUGE_VAL : HUGE_VAL);
        tri = {p0, p0 + step, p2};
    } else {
        const Vec3 p0 = random.point(2.0);
        const Vec3 p1 = random.point(2.0);
        const double off = random.decade(-15.0, -3.0) * glm::length(p1 - p0);
        tri = {p0, p1,
               p0 + random.uniform(-0.5, 1.5) * (p1 - p0) + off * perpendicular(random, p1 - p0)};
    }
    const Vec3 target = on_triangle(tri, random.uniform(0.0, 1.0), random.uniform(0.0, 1.0));
    return single(
        ray_through(random, target + random.unit_vector() * random.uniform(2.0, 8.0), target), tri);
}

// Axis-parallel directions (two zero components) against a triangle, a sphere or a plane, the
// origin sometimes on a vertex's coordinate plane: the 0 * inf of a slab test, the zero
// determinants of a careless triangle test.
RayCase axis_parallel(PortableRandom& random) {
    const int axis = static_cast<int>(random.integer(0, 2));
    Vec3 direction(0.0);
    direction[axis] = (random.unit() < 0.5 ? -1.0 : 1.0) * random.decade(-1.0, 1.0);
    const double kind = random.unit();
    if (kind < 0.5) {
        const Triangle tri{random.point(2.0), random.point(2.0), random.point(2.0)};
        Vec3 origin = on_triangle(tri, random.uniform(-0.2, 1.2), random.uniform(-0.2, 1.2));
        if (random.unit() < 0.3) origin[(axis + 1) % 3] = tri.p1[(axis + 1) % 3];
        origin -= direction * random.uniform(1.0, 10.0);
        return single({origin, direction}, tri);
    }
    if (kind < 0.8) {
        const Sphere sphere{random.point(2.0), random.uniform(0.1, 2.0)};
        Vec3 origin = sphere.center + random.point(1.2 * sphere.radius);
        origin -= direction * random.uniform(3.0, 10.0);
        return single({origin, direction}, sphere);
    }
    const Plane plane{random.point(2.0), random.unit_vector()};
    return single({random.point(5.0), direction}, plane);
}

// Origins on the surface, as a reflection or shadow ray starts: within rounding of a triangle, a
// sphere or a plane, with t_min = 0, leaving or entering.
RayCase origin_on_surface(PortableRandom& random) {
    const double kind = random.unit();
    const Vec3 direction = random.unit_vector() * random.decade(-1.0, 1.0);
    if (kind < 0.4) {
        const Triangle tri{random.point(2.0), random.point(2.0), random.point(2.0)};
        return single(
            {on_triangle(tri, random.uniform(0.05, 0.45), random.uniform(0.05, 0.45)), direction},
            tri);
    }
    if (kind < 0.8) {
        const Sphere sphere{random.point(2.0), random.uniform(0.1, 3.0)};
        return single({sphere.center + random.unit_vector() * sphere.radius, direction}, sphere);
    }
    const Plane plane{random.point(2.0), random.unit_vector()};
    return single(
        {plane.point + perpendicular(random, plane.normal) * random.uniform(0.0, 3.0), direction},
        plane);
}

// Rays whose line passes at r (1 + delta) from the centre, delta 0 or +-1e-16 to +-1e-4.
RayCase tangent(PortableRandom& random) {
    const Sphere sphere{random.point(2.0), random.uniform(0.1, 3.0)};
    const Vec3 d = random.unit_vector();
    const Vec3 side = perpendicular(random, d);
    const double delta =
        random.unit() < 0.1 ? 0.0 : (random.unit() < 0.5 ? -1.0 : 1.0) * random.decade(-16.0, -4.0);
    const Vec3 touch = sphere.center + side * sphere.radius * (1.0 + delta);
    return single(ray_through(random, touch - d * random.uniform(2.0, 10.0) * sphere.radius, touch),
                  sphere);
}

RayCase tiny_sphere(PortableRandom& random) {
    const Sphere sphere{random.point(2.0), random.decade(-9.0, -3.0)};
    const Vec3 origin = sphere.center + random.unit_vector() * random.uniform(1.0, 10.0);
    return single(ray_through(random, origin, sphere.center + random.point(1.2 * sphere.radius)),
                  sphere);
}

RayCase huge_sphere(PortableRandom& random) {
    const Sphere sphere{random.point(2.0), random.decade(4.0, 8.0)};
    const Vec3 out = random.unit_vector();
    const Vec3 origin = sphere.center + out * (sphere.radius + random.decade(-1.0, 1.0));
    // Towards a point of the surface not far round from the origin.
    const Vec3 target = sphere.center + glm::normalize(out + random.point(0.01)) * sphere.radius *
                                            random.uniform(0.999, 1.001);
    return single(ray_through(random, origin, target), sphere);
}

RayCase far_sphere(PortableRandom& random) {
    const Vec3 origin = random.point(2.0);
    const Sphere sphere{origin + random.unit_vector() * random.decade(4.0, 7.0),
                        random.uniform(1e-3, 1.0)};
    return single(ray_through(random, origin, sphere.center + random.point(1.2 * sphere.radius)),
                  sphere);
}

// Just outside a large sphere, along an axis, with every intermediate exact: the centre at
// integer coordinates, radius R from 1e6 to 9e7, the origin x from 1 to 1000 units beside the
// tangent point (|f|^2 = x^2 + R^2 < 2^53). The near root x^2 / (R + sqrt(R^2 - x^2)) is tiny
// next to R: the stable roots get it to an ulp, the textbook formula loses most of its digits.
RayCase stable_roots(PortableRandom& random) {
    const auto coordinate = [&] { return static_cast<double>(random.integer(-1000, 1000)); };
    const Vec3 center{coordinate(), coordinate(), coordinate()};
    const auto radius = static_cast<double>(random.integer(1000000, 90000000));
    const auto x = static_cast<double>(random.integer(1, 1000));
    const int along = static_cast<int>(random.integer(0, 2));
    const int beside = (along + static_cast<int>(random.integer(1, 2))) % 3;
    const double sign = random.unit() < 0.5 ? -1.0 : 1.0;
    Vec3 origin = center;
    origin[along] += sign * radius;
    origin[beside] += x;
    Vec3 direction(0.0);
    direction[along] = -sign;
    return single({origin, direction}, Sphere{center, radius});
}

// closest_hit's family: a small scene, an icosahedron, two spheres and a floor plane, and a ray
// from outside through it.
RayCase closest_hit_scene(PortableRandom& random) {
    static const ClosedMesh icosahedron = icosphere(0);
    RayCase ray_case;
    const Placement placement{random_rotation(random), random.uniform(0.5, 1.5), random.point(1.0)};
    for (const auto& [a, b, c] : icosahedron.faces) {
        ray_case.primitives.push_back(
            {Triangle{placement(icosahedron.vertices[a]), placement(icosahedron.vertices[b]),
                      placement(icosahedron.vertices[c])},
             {}});
    }
    ray_case.primitives.push_back({Sphere{random.point(2.0), random.uniform(0.2, 1.0)}, {}});
    ray_case.primitives.push_back({Sphere{random.point(2.0), random.uniform(0.2, 1.0)}, {}});
    ray_case.primitives.push_back({Plane{{0, -2, 0}, {0, 1, 0}}, {}});
    const Vec3 origin = random.unit_vector() * random.uniform(6.0, 12.0);
    ray_case.ray = ray_through(random, origin, random.point(2.0));
    return ray_case;
}

}  // namespace

const std::vector<Stage3Family>& stage3_families() {
    static const std::vector<Stage3Family> families = {
        {"random-triangles",
         "random triangles, rays aimed in and around them, some with a short t_max", 0.0,
         random_triangle},
        {"random-spheres", "random spheres, rays aimed in and around them, one in ten from inside",
         0.0, random_sphere},
        {"random-planes", "random planes and rays", 0.0, random_plane},
        {"shared-edges",
         "rays through an edge two triangles of a closed mesh share (watertight off the "
         "silhouette)",
         0.0, shared_edge_near},
        {"shared-edges-far", "the same with the mesh 1e5 to 1e6 from the origin", 0.0,
         shared_edge_far},
        {"shared-vertices",
         "rays through a vertex of a closed mesh, against its fan (watertight off the silhouette)",
         0.0, shared_vertex_near},
        {"shared-vertices-far", "the same with the mesh 1e5 to 1e6 from the origin", 0.0,
         shared_vertex_far},
        {"grazing", "rays 1e-2 to 1e-12 radians off the triangle's plane", 0.0, grazing},
        {"in-plane", "rays exactly in the triangle's plane: a miss by the contract", 0.0, in_plane},
        {"slivers", "nearly degenerate triangles, and exactly degenerate ones (a miss)", 0.0,
         sliver},
        {"axis-parallel", "directions along an axis, origins on vertex coordinate planes", 0.0,
         axis_parallel},
        {"origins-on-surface", "rays starting on a triangle, sphere or plane, t_min = 0", 0.0,
         origin_on_surface},
        {"tangent-rays", "lines at r (1 + delta) from a sphere's centre, |delta| <= 1e-4", 0.0,
         tangent},
        {"tiny-spheres", "radii 1e-9 to 1e-3, 1 to 10 away", 0.0, tiny_sphere},
        {"huge-spheres", "radii 1e4 to 1e8, the origin just outside", 0.0, huge_sphere},
        {"far-spheres", "radii 1e-3 to 1, 1e4 to 1e7 away", 0.0, far_sphere},
        {"stable-roots",
         "just outside a large sphere, all exact: t within 16 ulps (the stable form)", 16.0,
         stable_roots},
        {"closest-hit-scene", "an icosahedron, two spheres and a plane: the closest of 23", 0.0,
         closest_hit_scene},
    };
    return families;
}

const Stage3Family* find_stage3_family(std::string_view name) {
    for (const Stage3Family& family : stage3_families()) {
        if (name == family.name) return &family;
    }
    return nullptr;
}

CaseFamily generate_cases(const Stage3Family& family, std::uint64_t seed, std::size_t count) {
    CaseFamily cases;
    cases.name = family.name;
    cases.seed = seed;
    cases.description = family.description;
    cases.cases.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        PortableRandom random(seed, k);
        RayCase ray_case = family.make(random);
        ray_case.index = k;
        cases.cases.push_back(std::move(ray_case));
    }
    return cases;
}

}  // namespace raystep
