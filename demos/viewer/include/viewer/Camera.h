// The viewer's orbit camera, shared by every viewport (they all look at the same scene), and the
// little matrix maths OpenGL needs. Y is up, as in the scene library.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace viewer
{
/// 4x4 matrix, column-major (OpenGL's order): element (row r, column c) is m[c * 4 + r].
struct Mat4
{
	float m[16];
	static Mat4 identity();
	Mat4 operator*(const Mat4& other) const;
};

/// A camera on a sphere around `target`: yaw about the vertical, pitch above the horizon.
class OrbitCamera
{
public:
	btVector3 target{0, 1, 0};  ///< m, the point looked at
	double yaw = 0.45;          ///< rad, 0 = looking along -z
	double pitch = 0.3;         ///< rad above the horizontal (looking down)
	double distance = 10;       ///< m from target
	double fovY = 0.7;          ///< rad, vertical field of view

	btVector3 eye() const;
	Mat4 view() const;
	/// Perspective with near/far planes scaled to the distance (so close-ups and 100 m scenes both work).
	Mat4 projection(double aspect) const;

	void orbit(double dYaw, double dPitch);  ///< rad; pitch stays within 1..85 degrees (above the ground)
	void zoom(double factor);                ///< distance *= factor
	/// Moves target and eye sideways / up by fractions of the visible height at the target.
	void pan(double dxFraction, double dyFraction);

	/// Places target and distance so the box [lo, hi] fits a viewport of `aspect` with a margin,
	/// keeping yaw and pitch.
	void frame(const btVector3& lo, const btVector3& hi, double aspect);

	/// World-space ray through normalized device coordinates (-1..1, y up).
	void ray(double ndcX, double ndcY, double aspect, btVector3& origin, btVector3& direction) const;
	/// Normalized device coordinates of a point; false if it is behind the camera.
	bool project(const btVector3& point, double aspect, double& ndcX, double& ndcY) const;

private:
	void basis(btVector3& forward, btVector3& right, btVector3& up) const;
};

/// Union of the bodies' AABBs (bodies with a non-finite or huge one left out); false (lo, hi
/// untouched) if none is left.
bool bodyBounds(const std::vector<btRigidBody*>& bodies, btVector3& lo, btVector3& hi);
}  // namespace viewer
