#pragma once

#include "stages/1_vectors/vectors.h"
#include "stages/2_rays/ray.h"

namespace raystep {

// Stage 2: cameras. Handout: docs/stage2.md, "The perspective camera".
//
// Pixels: (i, j) is column i from the left and row j from the top, i in [0, width),
// j in [0, height); row 0 is the top row of the image file. A ray goes through the pixel's
// centre, (i + 0.5, j + 0.5) in these coordinates.

/// The perspective camera of `camera lookfrom lookat up fovy`, ready to make rays.
struct PerspectiveCamera {
    Vec3 eye;            ///< lookfrom
    Frame frame;         ///< orthonormal_frame(lookfrom - lookat, up): u right, v up, w backwards
    double half_width;   ///< tan(fovx / 2): half the image plane's width at distance 1 from the eye
    double half_height;  ///< tan(fovy / 2)
    int width;           ///< image size in pixels
    int height;
};

/// The camera at lookfrom looking at lookat, `up` giving the image's upward direction, with
/// vertical field of view fovy (degrees) over an image of width x height pixels; the horizontal
/// field of view follows from the aspect ratio. Throws std::domain_error unless
/// 0 < fovy < 180, width >= 1 and height >= 1, and for a frame orthonormal_frame rejects.
PerspectiveCamera make_perspective_camera(const Vec3& lookfrom, const Vec3& lookat, const Vec3& up,
                                          double fovy_degrees, int width, int height);

/// The ray from the eye through the centre of pixel (i, j), with a unit direction and
/// t in [0, infinity).
Ray perspective_ray(const PerspectiveCamera& camera, int i, int j);

/// The orthographic camera of `camera` plus `ortho left right bottom top`: parallel rays along
/// -w from the plane through the eye, over the window [left, right] x [bottom, top] measured
/// along u and v.
struct OrthographicCamera {
    Vec3 eye;
    Frame frame;
    double left;
    double right;
    double bottom;
    double top;
    int width;
    int height;
};

/// Throws std::domain_error unless left < right and bottom < top with a finite width right - left
/// and height top - bottom (so a NaN or infinite edge throws: it would give rays with NaN or
/// infinite origins), width >= 1 and height >= 1, and for a frame orthonormal_frame rejects.
OrthographicCamera make_orthographic_camera(const Vec3& lookfrom, const Vec3& lookat,
                                            const Vec3& up, double left, double right,
                                            double bottom, double top, int width, int height);

/// The ray through the centre of pixel (i, j): origin on the window in the plane through the
/// eye, direction -w, t in [0, infinity).
Ray orthographic_ray(const OrthographicCamera& camera, int i, int j);

}  // namespace raystep
