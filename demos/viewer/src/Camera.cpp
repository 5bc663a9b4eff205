#include "viewer/Camera.h"

#include <algorithm>
#include <cmath>

namespace viewer
{
Mat4 Mat4::identity()
{
	Mat4 r{};
	r.m[0] = r.m[5] = r.m[10] = r.m[15] = 1;
	return r;
}

Mat4 Mat4::operator*(const Mat4& o) const
{
	Mat4 r{};
	for (int c = 0; c < 4; ++c)
		for (int row = 0; row < 4; ++row)
		{
			float sum = 0;
			for (int k = 0; k < 4; ++k) sum += m[k * 4 + row] * o.m[c * 4 + k];
			r.m[c * 4 + row] = sum;
		}
	return r;
}

void OrbitCamera::basis(btVector3& forward, btVector3& right, btVector3& up) const
{
	// Eye on the sphere: behind the target along +z rotated by yaw, lifted by pitch.
	const double cp = std::cos(pitch), sp = std::sin(pitch);
	const double cy = std::cos(yaw), sy = std::sin(yaw);
	forward = btVector3(btScalar(-sy * cp), btScalar(-sp), btScalar(-cy * cp));
	right = forward.cross(btVector3(0, 1, 0)).normalized();
	up = right.cross(forward);
}

btVector3 OrbitCamera::eye() const
{
	btVector3 f, r, u;
	basis(f, r, u);
	return target - f * btScalar(distance);
}

Mat4 OrbitCamera::view() const
{
	btVector3 f, r, u;
	basis(f, r, u);
	const btVector3 e = eye();
	Mat4 v = Mat4::identity();
	const btVector3 rows[3] = {r, u, -f};
	for (int i = 0; i < 3; ++i)
	{
		v.m[0 * 4 + i] = float(rows[i].x());
		v.m[1 * 4 + i] = float(rows[i].y());
		v.m[2 * 4 + i] = float(rows[i].z());
		v.m[3 * 4 + i] = float(-rows[i].dot(e));
	}
	return v;
}

Mat4 OrbitCamera::projection(double aspect) const
{
	const double nearPlane = std::max(0.01, distance * 0.02), farPlane = distance * 20 + 200;
	const double t = 1.0 / std::tan(fovY / 2);
	Mat4 p{};
	p.m[0] = float(t / aspect);
	p.m[5] = float(t);
	p.m[10] = float((farPlane + nearPlane) / (nearPlane - farPlane));
	p.m[11] = -1;
	p.m[14] = float(2 * farPlane * nearPlane / (nearPlane - farPlane));
	return p;
}

void OrbitCamera::orbit(double dYaw, double dPitch)
{
	// Above the ground (seen from below it hides everything) and short of straight down.
	const double lowest = 1.0 * M_PI / 180.0, highest = 85.0 * M_PI / 180.0;
	yaw += dYaw;
	pitch = std::max(lowest, std::min(highest, pitch + dPitch));
}

void OrbitCamera::zoom(double factor)
{
	distance = std::max(0.1, std::min(1000.0, distance * factor));
}

void OrbitCamera::pan(double dxFraction, double dyFraction)
{
	btVector3 f, r, u;
	basis(f, r, u);
	const double visibleHeight = 2 * distance * std::tan(fovY / 2);
	target += (r * btScalar(dxFraction) + u * btScalar(dyFraction)) * btScalar(visibleHeight);
}

void OrbitCamera::frame(const btVector3& lo, const btVector3& hi, double aspect)
{
	// Fit the bounding sphere in the narrower of the two fields of view, 10% margin.
	target = (lo + hi) * btScalar(0.5);
	const double radius = std::max(0.25, double((hi - lo).length()) * 0.5);
	const double halfFov = std::min(fovY / 2, std::atan(std::tan(fovY / 2) * aspect));
	distance = 1.1 * radius / std::sin(halfFov);
}

void OrbitCamera::ray(double ndcX, double ndcY, double aspect, btVector3& origin, btVector3& direction) const
{
	btVector3 f, r, u;
	basis(f, r, u);
	const double t = std::tan(fovY / 2);
	origin = eye();
	direction = (f + r * btScalar(ndcX * t * aspect) + u * btScalar(ndcY * t)).normalized();
}

bool OrbitCamera::project(const btVector3& point, double aspect, double& ndcX, double& ndcY) const
{
	btVector3 f, r, u;
	basis(f, r, u);
	const btVector3 d = point - eye();
	const double depth = d.dot(f);
	if (depth <= 0) return false;
	const double t = std::tan(fovY / 2);
	ndcX = d.dot(r) / (depth * t * aspect);
	ndcY = d.dot(u) / (depth * t);
	return true;
}

bool bodyBounds(const std::vector<btRigidBody*>& bodies, btVector3& lo, btVector3& hi)
{
	bool any = false;
	for (const btRigidBody* b : bodies)
	{
		btVector3 bmin, bmax;
		b->getCollisionShape()->getAabb(b->getWorldTransform(), bmin, bmax);
		const btScalar span = (bmax - bmin).length2() + bmin.length2();
		if (!(span < btScalar(1e12))) continue;  // NaN, Inf or flung far away: not part of the picture
		if (!any)
		{
			lo = bmin;
			hi = bmax;
			any = true;
		}
		lo.setMin(bmin);
		hi.setMax(bmax);
	}
	return any;
}
}  // namespace viewer
