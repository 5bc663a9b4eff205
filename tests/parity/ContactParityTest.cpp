// Contacts: friction on a kinematic turntable, continuous collision detection, independence of
// the order bodies are added in, and the contact callbacks applications hook into.
#include "ParityFixture.h"

#include <gtest/gtest.h>

namespace parity
{
namespace
{
/// A kinematic body's motion, as Bullet apps drive one: the world reads the motion state before
/// each step (saveKinematicState) and derives the body's velocity from the change.
class SpinningMotionState : public btMotionState
{
public:
	SpinningMotionState(const btVector3& centre, double rate) : m_centre(centre), m_rate(rate) {}
	/// The turntable's pose at time t (s): a turn of rate * t about the vertical axis.
	void setTime(double t) { m_angle = m_rate * t; }
	void getWorldTransform(btTransform& transform) const override
	{
		transform = btTransform(btQuaternion(btVector3(0, 1, 0), btScalar(m_angle)), m_centre);
	}
	void setWorldTransform(const btTransform&) override {}

private:
	btVector3 m_centre;
	double m_rate;
	double m_angle = 0;
};

/// A kinematic body sliding along x at a constant speed, driven through its motion state.
class SlidingMotionState : public btMotionState
{
public:
	SlidingMotionState(const btVector3& start, double speed) : m_start(start), m_speed(speed) {}
	void setTime(double t) { m_offset = m_speed * t; }
	void getWorldTransform(btTransform& transform) const override
	{
		transform = btTransform(btQuaternion::getIdentity(), m_start + vec(m_offset, 0, 0));
	}
	void setWorldTransform(const btTransform&) override {}

private:
	btVector3 m_start;
	double m_speed;
	double m_offset = 0;
};

/// How far the lowest corner of a cube of the given half edge is below the plane y = 0 (m, 0 if above).
double sinking(const btRigidBody& cube, double half)
{
	const btMatrix3x3& r = cube.getWorldTransform().getBasis();
	double reach = 0;
	for (int k = 0; k < 3; ++k) reach += half * std::fabs(double(r[1][k]));
	return std::max(0.0, reach - double(cube.getCenterOfMassPosition().y()));
}

/// Values of one measure across insertion orders: the same within 10 % of the largest value, or
/// within 0.5 mm, whichever is larger.
void expectSameAcrossOrders(const std::vector<double>& v, const char* what, Mode mode)
{
	const double lo = *std::min_element(v.begin(), v.end());
	const double hi = *std::max_element(v.begin(), v.end());
	const double allowed = std::max(0.1 * hi, 0.0005);
	EXPECT_LE(hi - lo, allowed) << modeName(mode) << ": " << what << " differs across insertion orders (" << lo * 1000 << " .. " << hi * 1000 << " mm)";
}

/// Rotation about +y of the body's x axis (rad, in (-pi, pi]).
double yawOf(const btRigidBody& body)
{
	const btVector3 x = body.getWorldTransform().getBasis().getColumn(0);
	return std::atan2(-double(x.z()), double(x.x()));
}
}  // namespace

// A kinematic turntable (1 rad/s about the vertical, driven through its motion state) carries two
// stacked cubes off-centre. Friction spins them up from rest (they slip briefly at the start, so
// they lag the table a little) and then carries them round: after 3 s the top cube has turned
// through what it turns under stock Bullet.
TEST(ContactParity, KinematicTurntable)
{
	constexpr double kRate = 1.0;  // rad/s
	constexpr double kSeconds = 3.0;
	constexpr double kYawTolerance = 0.05;	// fraction of stock's yaw
	PerMode<double> yaw;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		Scene scene(mode);
		SpinningMotionState* motion = new SpinningMotionState(vec(0, 0, 0), kRate);
		btTransform start;
		motion->getWorldTransform(start);
		// 4 x 0.2 x 4 m table, top face at y = 0.1; no ground needed (kinematic bodies do not fall).
		btRigidBody* table = scene.addBody(new btBoxShape(vec(2, 0.1, 2)), 0, start, false, -1, -1, motion);
		table->setCollisionFlags(table->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
		table->setActivationState(DISABLE_DEACTIVATION);
		// Two 0.5 m cubes, the lower one resting on the table 1 m from the axis.
		btRigidBody* lower = scene.addBox(vec(0.25, 0.25, 0.25), 1.0, vec(1.0, 0.1 + 0.25 - kOverlap, 0));
		btRigidBody* upper = scene.addBox(vec(0.25, 0.25, 0.25), 1.0, vec(1.0, 0.1 + 0.75 - 2 * kOverlap, 0));
		// Friction 1 on table and cubes (Bullet multiplies the two): the cubes catch up with
		// the table within a few steps instead of slipping for half a second.
		for (btRigidBody* b : {table, lower, upper}) b->setFriction(btScalar(1));

		double turned = 0;
		double previous = yawOf(*upper);
		for (int i = 0; i < scene.stepsFor(kSeconds); ++i)
		{
			motion->setTime((scene.steps() + 1) * scene.timeStep());  // pose at the end of this step
			scene.step();
			double delta = yawOf(*upper) - previous;
			if (delta > kPi) delta -= 2 * kPi;
			if (delta < -kPi) delta += 2 * kPi;
			turned += delta;
			previous += delta;
		}
		yaw[mode] = turned;
		text[mode] = "top cube yaw " + fmt(turned, "rad") + " (table " + fmt(kRate * kSeconds, "rad", 2) + ")";
	}
	printParity("Kinematic turntable 1 rad/s, 2 cubes, 3 s", text);

	ASSERT_GT(yaw[Mode::Stock], 0.5 * kRate * kSeconds) << "stock Bullet does not carry the cubes: the scene is wrong";
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		// The cubes ride the table by friction with the kinematic body's velocity, as in stock.
		EXPECT_NEAR(yaw[mode], yaw[Mode::Stock], kYawTolerance * yaw[Mode::Stock]);
	}
}

// A kinematic pusher slides at 0.5 mm/s (half the plugin's convergence speed at 60 Hz) and pushes
// a 10 kg plate over frictionless ground; two stacked 1 kg cubes ride on the plate (friction 0.8).
// Static friction holds far more than the cubes need, so physics says they move with the plate:
// after 10 s neither has slipped on it. D32 hides a support's motion slower than the convergence
// speed from the layer above, as the solve's error; a moving kinematic body drives the plate, and
// what it drives carries its load (docs/history.md, section 4t). Stock Bullet lets the top cube
// creep (about 2 mm in 10 s).
TEST(ContactParity, SlowlyPushedPlateCarriesItsStack)
{
	constexpr double kSpeed = 5e-4;	 // m/s
	constexpr double kSeconds = 10.0;
	constexpr double kSlipLimit = 2e-4;	 // m: physics says 0
	PerMode<double> slip;
	PerMode<double> travel;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		Scene scene(mode);
		btRigidBody* ground = scene.addGround();
		ground->setFriction(0);
		btRigidBody* plate = scene.addBox(vec(1, 0.1, 1), 10.0, vec(0, 0.1 - kOverlap, 0));
		btRigidBody* lower = scene.addBox(vec(0.25, 0.25, 0.25), 1.0, vec(0, 0.2 + 0.25 - 2 * kOverlap, 0));
		btRigidBody* upper = scene.addBox(vec(0.25, 0.25, 0.25), 1.0, vec(0, 0.2 + 0.75 - 3 * kOverlap, 0));
		for (btRigidBody* b : {plate, lower, upper}) b->setFriction(btScalar(0.8));
		// The pusher's face touches the plate's left face; it slides no lower than the plate's top.
		SlidingMotionState* motion = new SlidingMotionState(vec(-1.1 + kOverlap, 0.1, 0), kSpeed);
		btTransform start;
		motion->getWorldTransform(start);
		btRigidBody* pusher = scene.addBody(new btBoxShape(vec(0.1, 0.09, 1)), 0, start, false, -1, -1, motion);
		pusher->setCollisionFlags(pusher->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
		pusher->setActivationState(DISABLE_DEACTIVATION);
		pusher->setFriction(0);
		const double plate0 = plate->getCenterOfMassPosition().x();
		const double lower0 = lower->getCenterOfMassPosition().x() - plate0;
		const double upper0 = upper->getCenterOfMassPosition().x() - plate0;
		for (int i = 0; i < scene.stepsFor(kSeconds); ++i)
		{
			motion->setTime((scene.steps() + 1) * scene.timeStep());  // pose at the end of this step
			scene.step();
		}
		const double plateX = plate->getCenterOfMassPosition().x();
		const double lowerSlip = lower->getCenterOfMassPosition().x() - plateX - lower0;
		const double upperSlip = upper->getCenterOfMassPosition().x() - plateX - upper0;
		slip[mode] = std::max(std::fabs(lowerSlip), std::fabs(upperSlip));
		travel[mode] = plateX - plate0;
		text[mode] = "plate moved " + fmt(1000 * travel[mode], "mm", 2) + ", cubes slipped " + fmt(1000 * lowerSlip, "mm", 3) + " / " +
					 fmt(1000 * upperSlip, "mm", 3);
	}
	printParity("Plate pushed at 0.5 mm/s, 2 cubes on it, 10 s", text);

	ASSERT_GT(travel[Mode::Stock], 0.5 * kSpeed * kSeconds) << "stock Bullet does not push the plate: the scene is wrong";
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		EXPECT_GT(travel[mode], 0.5 * kSpeed * kSeconds) << "m: the pusher moves the plate";
		EXPECT_LT(slip[mode], kSlipLimit) << "m: the cubes ride with the plate";
	}
}

// A small fast sphere (r 5 cm, 100 m/s: 1.7 m per step at 60 Hz) with CCD enabled is fired at a
// 2 cm static wall. Bullet's CCD (motion clamping and predictive contacts) must stop it in front
// of the wall in every mode: its centre never passes the wall's mid-plane.
// Without gravity nothing rests on anything, so every group is Bullet's own solve (D9) and the
// plugin must step exactly as stock: a box pushed at 1 m/s into a row of two others, 3 s, with
// warm starting (the plugin's warm-start limit must not zero it where there is no weight).
TEST(ContactParity, ZeroGravityCollisionsAreStocks)
{
	PerMode<btVector3> last;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		Scene scene(mode, kTimeStep, vec(0, 0, 0));
		btRigidBody* mover = scene.addBox(vec(0.5, 0.5, 0.5), 1.0, vec(-2, 0, 0));  // hits the row at 1 s
		scene.addBox(vec(0.5, 0.5, 0.5), 1.0, vec(0, 0, 0));
		btRigidBody* end = scene.addBox(vec(0.5, 0.5, 0.5), 2.0, vec(1.0 - kOverlap, 0, 0));
		mover->setLinearVelocity(vec(1, 0, 0));
		for (int i = 0; i < scene.stepsFor(3.0); ++i) scene.step();
		last[mode] = end->getCenterOfMassPosition();
		text[mode] = "last box x " + fmt(last[mode].x(), "m", 6);
	}
	printParity("Zero gravity: a box pushed into two others, 3 s", text);
	ASSERT_GT(last[Mode::Stock].x(), 1.1) << "the push must move the last box";
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		EXPECT_NEAR(last[mode].x(), last[Mode::Stock].x(), 1e-6) << "m: a group without stacks is Bullet's own solve";
	}
}

TEST(ContactParity, CcdStopsFastSphere)
{
	constexpr double kRadius = 0.05;
	constexpr double kSpeed = 100.0;
	PerMode<double> farthest;
	PerMode<double> finalX;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		Scene scene(mode);
		scene.addBox(vec(0.01, 2, 2), 0, vec(0, 0, 0));	 // wall: x in [-0.01, 0.01]
		btRigidBody* ball = scene.addSphere(kRadius, 0.1, vec(-2, 0, 0));
		ball->setLinearVelocity(vec(kSpeed, 0, 0));
		ball->setCcdMotionThreshold(btScalar(kRadius));
		ball->setCcdSweptSphereRadius(btScalar(0.8 * kRadius));
		double maxX = -1e9;
		for (int i = 0; i < scene.stepsFor(0.25); ++i)
		{
			scene.step();
			maxX = std::max(maxX, double(ball->getCenterOfMassPosition().x()));
		}
		farthest[mode] = maxX;
		finalX[mode] = ball->getCenterOfMassPosition().x();
		text[mode] = "max centre x " + fmt(maxX * 1000, "mm", 1) + ", final x " + fmt(finalX[mode] * 1000, "mm", 1);
	}
	printParity("CCD sphere r 5 cm at 100 m/s vs 2 cm wall (x = 0)", text);

	ASSERT_LT(farthest[Mode::Stock], 0.0) << "stock Bullet lets the sphere tunnel: the scene is wrong";
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		EXPECT_LT(farthest[mode], 0.0) << "the sphere tunnelled into or through the wall";
		EXPECT_LT(finalX[mode], 0.0) << "the sphere ended behind the wall";
	}
}

// The same scene built in three insertion orders: a 2-box tower (A, C on A), a cube B 3 m away and
// a cube D dropped beside the tower. Physics does not depend on the order bodies were added in:
// D's landing penetration (how far its lowest corner sinks below the ground after a step) and the
// tower's drift must agree across orders.
TEST(ContactParity, InsertionOrderIndependence)
{
	enum Piece
	{
		Ground,
		A,
		B,
		C,
		D
	};
	const std::vector<std::vector<Piece>> orders = {{Ground, A, B, C, D}, {D, C, B, A, Ground}, {B, D, Ground, C, A}};
	struct Result
	{
		double landing = 0;	 // m, deepest sinking of D's lowest corner below the ground over the run
		double drift = 0;	 // m, worst drift of the tower over the run
	};
	PerMode<std::vector<Result>> results;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		for (const auto& order : orders)
		{
			Scene scene(mode);
			btRigidBody* body[5] = {};
			const btVector3 half = vec(0.5, 0.5, 0.5);
			for (Piece p : order)
			{
				switch (p)
				{
					case Ground:
						body[p] = scene.addGround();
						break;
					case A:
						body[p] = scene.addBox(half, 1.0, vec(0, 0.5 - kOverlap, 0));
						break;
					case B:
						body[p] = scene.addBox(half, 1.0, vec(3, 0.5 - kOverlap, 0));
						break;
					case C:
						body[p] = scene.addBox(half, 1.0, vec(0, 1.5 - 2 * kOverlap, 0));
						break;
					case D:
						body[p] = scene.addBox(half, 1.0, vec(1.5, 1.5, 0));  // bottom 1 m above the ground, 0.5 m from A
						break;
				}
			}
			DriftTracker tower({body[A], body[C]});
			Result r;
			for (int i = 0; i < scene.stepsFor(2.0); ++i)
			{
				scene.step();
				tower.update();
				r.landing = std::max(r.landing, sinking(*body[D], 0.5));
			}
			r.drift = tower.worst();
			results[mode].push_back(r);
		}
		std::string t = "landing";
		for (const Result& r : results[mode]) t += " " + fmt(r.landing * 1000, "", 2);
		t += " mm, tower drift";
		for (const Result& r : results[mode]) t += " " + fmt(r.drift * 1000, "", 3);
		text[mode] = t + " mm";
	}
	printParity("Insertion order (3 orders): D landing penetration, tower drift", text);

	// Same within 10 % of the largest value, or within 0.5 mm, whichever is larger.
	for (Mode mode : kPluginModes)
	{
		std::vector<double> landing, drift;
		for (const Result& r : results[mode])
		{
			landing.push_back(r.landing);
			drift.push_back(r.drift);
		}
		expectSameAcrossOrders(landing, "landing penetration", mode);
		expectSameAcrossOrders(drift, "tower drift", mode);
	}
}

namespace
{
int gAddedCount = 0;
int gProcessedCount = 0;
bool countAdded(btManifoldPoint&, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*, int, int)
{
	++gAddedCount;
	return false;
}
bool countProcessed(btManifoldPoint&, void*, void*)
{
	++gProcessedCount;
	return false;
}

/// Installs the counting callbacks and restores the previous global pointers on exit.
class CallbackGuard
{
public:
	CallbackGuard() : m_added(gContactAddedCallback), m_processed(gContactProcessedCallback)
	{
		gContactAddedCallback = countAdded;
		gContactProcessedCallback = countProcessed;
	}
	~CallbackGuard()
	{
		gContactAddedCallback = m_added;
		gContactProcessedCallback = m_processed;
	}

private:
	ContactAddedCallback m_added;
	ContactProcessedCallback m_processed;
};
}  // namespace

// Applications count on Bullet's contact callbacks (gContactAddedCallback for bodies with
// CF_CUSTOM_MATERIAL_CALLBACK, gContactProcessedCallback for every kept point) being called as
// often as stock Bullet calls them: one narrowphase per step. Over 60 steps of a 3-box tower resting
// on the ground, processed points equal stock's within 10 % and added points stay within what one
// narrowphase per step can find. (A landing stack is no parity case for counts: the points found
// per step follow the bodies' trajectories, which differ between solvers.)
TEST(ContactParity, ContactCallbackCounts)
{
	constexpr double kTolerance = 0.10;
	PerMode<int> added;
	PerMode<int> processed;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		CallbackGuard guard;
		gAddedCount = 0;
		gProcessedCount = 0;
		{
			Scene scene(mode);
			scene.addGround();
			for (btRigidBody* box : scene.addTower(3, 1.0, 1.0, vec(0, 0, 0)))
				box->setCollisionFlags(box->getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
			for (int i = 0; i < 60; ++i) scene.step();
		}
		added[mode] = gAddedCount;
		processed[mode] = gProcessedCount;
		text[mode] = "added " + std::to_string(added[mode]) + ", processed " + std::to_string(processed[mode]);
	}
	printParity("Contact callbacks, 3-box tower resting, 60 steps", text);

	ASSERT_GT(added[Mode::Stock], 0);
	ASSERT_GT(processed[Mode::Stock], 0);
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		// One narrowphase per step: box-box finds at most 4 points per manifold per call, 3
		// manifolds, 60 steps. Stock itself finds fewer (its boxes jitter apart now and then), so
		// added points are bounded by that count and at least stock's less 10 %.
		EXPECT_LE(added[mode], 4 * 3 * 60) << "gContactAddedCallback calls: more than one narrowphase per step";
		EXPECT_GE(added[mode], (1 - kTolerance) * added[Mode::Stock]) << "gContactAddedCallback calls";
		EXPECT_NEAR(processed[mode], processed[Mode::Stock], kTolerance * processed[Mode::Stock]) << "gContactProcessedCallback calls";
	}
}
}  // namespace parity
