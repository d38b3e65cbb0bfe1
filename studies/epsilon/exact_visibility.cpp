#include "studies/epsilon/exact_visibility.h"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace raystep {

namespace {

using Real = long double;

// Decisions closer than this, relative to the sizes of what they compare, are left undecided.
constexpr Real kMargin = 1e-12L;

struct Real3 {
    Real x, y, z;
};

Real3 real(const Vec3& v) {
    return {v.x, v.y, v.z};
}
Real3 operator+(const Real3& a, const Real3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Real3 operator-(const Real3& a, const Real3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Real3 operator*(Real s, const Real3& a) {
    return {s * a.x, s * a.y, s * a.z};
}
Real dot(const Real3& a, const Real3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
Real3 cross(const Real3& a, const Real3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Real length(const Real3& a) {
    return std::sqrt(dot(a, a));
}

// Where a line O + t D meets one primitive, as far as it can be decided: `hit` says whether it
// meets it at all (for the t range asked), `t` where, within `tolerance`.
struct Crossing {
    Decided hit = Decided::no;
    Real t = 0;
    Real tolerance = 0;
};

// The range of t that counts: (0, infinity) for a camera ray, (0, 1) for the segment from a
// point to a light.
struct Range {
    Real high;
};

// Whether t lies in (0, high), given its tolerance.
Decided in_range(Real t, Real tolerance, const Range& range) {
    if (t > tolerance && t < range.high - tolerance) return Decided::yes;
    if (t < -tolerance || t > range.high + tolerance) return Decided::no;
    return Decided::undecided;
}

Crossing sphere_crossing(const Sphere& sphere, const Real3& o, const Real3& d, const Range& range) {
    const Real3 f = o - real(sphere.center);
    const Real a = dot(d, d);
    const Real b = dot(f, d);
    const Real r = sphere.radius;
    const Real k = dot(f, f) - r * r;
    const Real discriminant = b * b - a * k;
    const Real size = b * b + std::abs(a * k);
    if (discriminant < -kMargin * size) return {};
    if (discriminant <= kMargin * size) return {Decided::undecided, -b / a, 0};
    const Real root = std::sqrt(discriminant);
    const Real tolerance = kMargin * (std::abs(b) + root) / a;
    for (const Real t : {(-b - root) / a, (-b + root) / a}) {
        const Decided inside = in_range(t, tolerance, range);
        if (inside != Decided::no) return {inside, t, tolerance};
    }
    return {};
}

Crossing triangle_crossing(const Triangle& triangle, const Real3& o, const Real3& d,
                           const Range& range) {
    const Real3 p0 = real(triangle.p0);
    const Real3 e1 = real(triangle.p1) - p0;
    const Real3 e2 = real(triangle.p2) - p0;
    const Real3 p = cross(d, e2);
    const Real det = dot(e1, p);
    const Real3 s = o - p0;
    if (std::abs(det) <= kMargin * length(e1) * length(d) * length(e2)) {
        // Parallel to the plane: a miss, unless the line lies in it.
        const Real3 n = cross(e1, e2);
        if (std::abs(dot(s, n)) > kMargin * length(s) * length(n)) return {};
        return {Decided::undecided, 0, 0};
    }
    const Real beta = dot(s, p) / det;
    const Real3 q = cross(s, e1);
    const Real gamma = dot(d, q) / det;
    const Real t = dot(e2, q) / det;
    const Real tolerance = kMargin * (std::abs(t) + length(s) / length(d));
    Decided inside = Decided::yes;
    for (const Real w : {beta, gamma, 1 - beta - gamma}) {
        if (w < -kMargin) return {};
        if (w <= kMargin) inside = Decided::undecided;
    }
    const Decided ranged = in_range(t, tolerance, range);
    if (ranged == Decided::no) return {};
    return {ranged == Decided::yes ? inside : Decided::undecided, t, tolerance};
}

Crossing plane_crossing(const Plane& plane, const Real3& o, const Real3& d, const Range& range) {
    const Real3 n = real(plane.normal);
    const Real3 to_plane = real(plane.point) - o;
    const Real denominator = dot(d, n);
    const Real numerator = dot(to_plane, n);
    if (std::abs(denominator) <= kMargin * length(d) * length(n)) {
        if (std::abs(numerator) > kMargin * length(to_plane) * length(n)) return {};
        return {Decided::undecided, 0, 0};
    }
    const Real t = numerator / denominator;
    const Real tolerance =
        kMargin * (std::abs(t) + length(to_plane) * length(n) / std::abs(denominator));
    const Decided ranged = in_range(t, tolerance, range);
    if (ranged == Decided::no) return {};
    return {ranged, t, tolerance};
}

// Every primitive's crossing with the line, each with its reference.
struct Candidate {
    PrimitiveRef primitive;
    Crossing crossing;
};

std::vector<Candidate> crossings(const Scene& scene, const Real3& o, const Real3& d,
                                 const Range& range) {
    std::vector<Candidate> found;
    const auto add = [&](PrimitiveRef::Kind kind, std::size_t index, const Crossing& crossing) {
        if (crossing.hit != Decided::no) found.push_back({{kind, index}, crossing});
    };
    for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
        add(PrimitiveRef::Kind::sphere, k, sphere_crossing(scene.spheres[k].shape, o, d, range));
    }
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        add(PrimitiveRef::Kind::triangle, k,
            triangle_crossing(scene.triangles[k].shape, o, d, range));
    }
    for (std::size_t k = 0; k < scene.planes.size(); ++k) {
        add(PrimitiveRef::Kind::plane, k, plane_crossing(scene.planes[k].shape, o, d, range));
    }
    return found;
}

// The receiver's normal at the exact point, not normalized.
Real3 exact_normal(const Scene& scene, const PrimitiveRef& primitive, const Real3& point) {
    switch (primitive.kind) {
        case PrimitiveRef::Kind::sphere:
            return point - real(scene.spheres[primitive.index].shape.center);
        case PrimitiveRef::Kind::triangle: {
            const Triangle& t = scene.triangles[primitive.index].shape;
            return cross(real(t.p1) - real(t.p0), real(t.p2) - real(t.p0));
        }
        case PrimitiveRef::Kind::plane:
            return real(scene.planes[primitive.index].shape.normal);
    }
    throw std::logic_error("exact visibility: unknown primitive kind");
}

}  // namespace

ExactHit exact_first_hit(const Scene& scene, const Vec3& origin, const Vec3& direction) {
    const std::vector<Candidate> found =
        crossings(scene, real(origin), real(direction), Range{HUGE_VALL});
    const Candidate* best = nullptr;
    for (const Candidate& c : found) {
        if (c.crossing.hit == Decided::yes && (!best || c.crossing.t < best->crossing.t)) best = &c;
    }
    // Anything that may be as near as the best makes the first hit uncertain: an undecided
    // crossing (a silhouette) or a second hit within the tolerances (a near tie).
    for (const Candidate& c : found) {
        if (&c == best) continue;
        const bool may_be_nearer = !best || c.crossing.t - c.crossing.tolerance <=
                                                best->crossing.t + best->crossing.tolerance;
        if (may_be_nearer && (c.crossing.hit == Decided::undecided || best)) {
            return {false, std::nullopt, 0};
        }
    }
    if (!best) return {};
    return {true, best->primitive, best->crossing.t};
}

Decided exact_light_reaches(const Scene& scene, const Vec3& origin, const Vec3& direction,
                            const ExactHit& hit, const Vec3& light) {
    if (!hit.decided || !hit.primitive) return Decided::undecided;
    const Real3 point = real(origin) + hit.t * real(direction);
    const Real3 to_light = real(light) - point;
    const Real3 normal = exact_normal(scene, *hit.primitive, point);

    // The side the ray came from is the side opposite its direction.
    const Real light_side = dot(to_light, normal);
    const Real eye_side = -dot(real(direction), normal);
    if (std::abs(light_side) <= kMargin * length(to_light) * length(normal)) {
        return Decided::undecided;
    }
    if ((light_side > 0) != (eye_side > 0)) return Decided::no;

    // The receiver cannot shadow itself from the side the light is on: a plane or triangle is
    // flat, a sphere convex. Every other primitive may cross the segment.
    Decided reaches = Decided::yes;
    for (const Candidate& c : crossings(scene, point, to_light, Range{1})) {
        if (c.primitive == *hit.primitive) continue;
        if (c.crossing.hit == Decided::yes) return Decided::no;
        reaches = Decided::undecided;
    }
    return reaches;
}

}  // namespace raystep
