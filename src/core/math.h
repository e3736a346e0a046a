// Small fixed-size linear algebra for development and placement.
// The physics engine has its own types; these are the ones the rest of
// Bestiary speaks (double precision, as ODE is built here).
#pragma once

#include <array>
#include <cmath>

namespace bx {

/// A 3-vector.
struct Vec3 {
  double x = 0, y = 0, z = 0;

  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend Vec3 operator*(Vec3 a, double s) { return s * a; }
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a) {
  double n = norm(a);
  return n > 0 ? (1.0 / n) * a : Vec3{1, 0, 0};
}

/// A 3x3 matrix, row-major: m[row][col]. Rotation matrices map local to world.
struct Mat3 {
  std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

  static Mat3 identity() { return {}; }
  static Mat3 diag(double a, double b, double c) {
    Mat3 r;
    r.m = {{{a, 0, 0}, {0, b, 0}, {0, 0, c}}};
    return r;
  }
  /// Rotation by `angle` radians about unit axis `a` (right-handed).
  static Mat3 rotation(Vec3 a, double angle) {
    a = normalized(a);
    double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    Mat3 r;
    r.m = {{{t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y},
            {t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x},
            {t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c}}};
    return r;
  }
  /// Matrix whose columns are the given vectors.
  static Mat3 from_columns(Vec3 c0, Vec3 c1, Vec3 c2) {
    Mat3 r;
    for (int i = 0; i < 3; ++i) r.m[i] = {c0[i], c1[i], c2[i]};
    return r;
  }
  Vec3 column(int j) const { return {m[0][j], m[1][j], m[2][j]}; }
  Mat3 transposed() const {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[j][i];
    return r;
  }
  double det() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
  friend Vec3 operator*(const Mat3& a, Vec3 v) {
    return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
            a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
            a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
  }
  friend Mat3 operator*(const Mat3& a, const Mat3& b) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
  }
  friend bool operator==(const Mat3&, const Mat3&) = default;
};

/// Rotation from intrinsic x-y-z Euler angles (roll about x, then pitch about the
/// new y, then yaw about the new z).
inline Mat3 euler_xyz(Vec3 angles) {
  return Mat3::rotation({1, 0, 0}, angles.x) * Mat3::rotation({0, 1, 0}, angles.y) *
         Mat3::rotation({0, 0, 1}, angles.z);
}

/// Unit quaternion (w, x, y, z) of a proper rotation matrix.
struct Quat {
  double w = 1, x = 0, y = 0, z = 0;
};
inline Quat to_quat(const Mat3& r) {
  const auto& m = r.m;
  double tr = m[0][0] + m[1][1] + m[2][2];
  Quat q;
  if (tr > 0) {
    double s = std::sqrt(tr + 1.0) * 2;
    q = {0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
  } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
    double s = std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2;
    q = {(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
  } else if (m[1][1] > m[2][2]) {
    double s = std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2;
    q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s};
  } else {
    double s = std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2;
    q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s};
  }
  return q;
}
/// The rotation matrix of quaternion q, normalized first (a file's quaternion
/// is rounded); q must not be 0.
inline Mat3 from_quat(Quat q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  const double w = q.w / n, x = q.x / n, y = q.y / n, z = q.z / n;
  Mat3 r;
  r.m = {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
  return r;
}

/// A rigid placement: position and proper rotation (local -> world).
struct Pose {
  Vec3 p;
  Mat3 R;
  Vec3 apply(Vec3 local) const { return p + R * local; }
  friend bool operator==(const Pose&, const Pose&) = default;
};

constexpr double kPi = 3.14159265358979323846;

}  // namespace bx
