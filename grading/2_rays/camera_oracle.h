#pragma once

// Stage 2's expectations in long double: the camera's frame and the ray through a pixel's
// centre, for perspective and orthographic cameras, with how far a right implementation in
// double may land from it. No CGAL: a frame, a tangent and a normalization, 11 bits beyond a
// double.

#include "base/math/types.h"
#include "grader/oracle/wide_vec.h"

namespace raystep {

/// A camera as the probe's camera calls take it: fovy for a perspective one, the window for an
/// orthographic one.
struct CameraCase {
    Vec3 lookfrom;
    Vec3 lookat;
    Vec3 up;
    int width = 1;
    int height = 1;
    bool orthographic = false;
    double fovy = 0.0;
    double left = 0.0;
    double right = 0.0;
    double bottom = 0.0;
    double top = 0.0;
};

/// The camera's frame, exactly enough: w = a / |a|, u = (up x w) / |up x w|, v = w x u, and the
/// sine between up and the view direction, by which the frame's rounding in double is magnified.
struct WideFrame {
    WideVec u;
    WideVec v;
    WideVec w;
    Wide up_sine;
};

/// The frame of camera `c`.
WideFrame wide_frame(const CameraCase& c);

/// A camera ray as the judge expects it: t over [0, infinity), a unit direction.
struct ExpectedCameraRay {
    Vec3 origin;
    double origin_tolerance;  ///< per coordinate, absolute
    Vec3 direction;
    double direction_tolerance;
};

/// The ray through pixel (i, j)'s centre of a perspective camera. Its tolerance covers what a
/// right implementation cannot help: a half angle a few roundings off, which the tangent
/// magnifies near 90 degrees, and a half width taken through atan as often as directly.
ExpectedCameraRay expected_perspective(const CameraCase& c, int i, int j);

/// The ray through pixel (i, j)'s centre of an orthographic camera: from the window point, along
/// -w.
ExpectedCameraRay expected_orthographic(const CameraCase& c, int i, int j);

}  // namespace raystep
