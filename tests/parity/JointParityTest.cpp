// Joints: energy of a swinging chain, joint feedback forces, breaking thresholds, hinge motors
// and the limits of slider and 6-dof constraints, each against stock Bullet on the same scene.
#include "ParityFixture.h"

#include <gtest/gtest.h>

namespace parity
{
namespace
{
constexpr double kLinkHalf = 0.25;	// m, half length of a chain link (links are 0.5 m long)
constexpr double kLinkMass = 1.0;	// kg
/// Chain links collide with nothing: these are pure joint tests.
constexpr int kNoCollisionGroup = 64;

/// A chain of count links hanging from a static point at anchor, along direction (a unit vector:
/// down for a hanging chain, sideways for one held out horizontally).
struct Chain
{
	std::vector<btRigidBody*> links;
	std::vector<btPoint2PointConstraint*> joints;  // joints[0] holds links[0] to the anchor
};

Chain addChain(Scene& scene, int count, const btVector3& anchor, const btVector3& direction)
{
	Chain chain;
	// Each link is a 0.5 m box along its local x axis, turned to lie along direction.
	const btVector3 x(1, 0, 0);
	btQuaternion turn = btQuaternion::getIdentity();
	const btVector3 axis = x.cross(direction);
	if (axis.length2() > btScalar(1e-12)) turn = btQuaternion(axis.normalized(), x.angle(direction));
	for (int i = 0; i < count; ++i)
	{
		const btVector3 centre = anchor + direction * btScalar(kLinkHalf * (2 * i + 1));
		btRigidBody* link = scene.addBody(new btBoxShape(vec(kLinkHalf, 0.05, 0.05)), kLinkMass, btTransform(turn, centre), false,
										  kNoCollisionGroup, 0);
		btPoint2PointConstraint* joint;
		if (i == 0)
			joint = new btPoint2PointConstraint(*link, vec(-kLinkHalf, 0, 0));
		else
			joint = new btPoint2PointConstraint(*chain.links.back(), *link, vec(kLinkHalf, 0, 0), vec(-kLinkHalf, 0, 0));
		chain.joints.push_back(scene.addConstraint(joint));
		chain.links.push_back(link);
	}
	return chain;
}
}  // namespace

// A chain of 4 links (0.5 m, 1 kg) released held out horizontally swings down. Joints do no work,
// so the swing should keep its energy; stock Bullet loses some to its joint error correction
// (about a quarter in 2 s). At 2 s the chain's energy above its rest pose (kinetic plus potential
// above the hanging chain) keeps at least 80 % of stock's. And since joints and gravity add no
// energy, at no step of the 2 s does the chain hold more than it was released with (5 % margin
// for Bullet's joint error correction; stock stays below it).
TEST(JointParity, PendulumChainKeepsEnergy)
{
	constexpr int kLinks = 4;
	constexpr double kSeconds = 2.0;
	constexpr double kMinFraction = 0.8;
	constexpr double kMaxGain = 1.05;
	const btVector3 anchor = vec(0, 3, 0);
	// Released horizontally, link i's centre is (i + 1/2) link lengths above its rest height.
	double released = 0;
	for (int i = 0; i < kLinks; ++i) released += kLinkMass * kGravity * kLinkHalf * (2 * i + 1);

	PerMode<double> energy;
	PerMode<double> peak;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		Scene scene(mode);
		Chain chain = addChain(scene, kLinks, anchor, vec(1, 0, 0));
		for (int s = 0; s < scene.stepsFor(kSeconds); ++s)
		{
			scene.step();
			double e = 0;
			for (int i = 0; i < kLinks; ++i)
			{
				const btRigidBody* link = chain.links[i];
				const double restHeight = anchor.y() - kLinkHalf * (2 * i + 1);
				e += kineticEnergy(*link) + kLinkMass * kGravity * (link->getCenterOfMassPosition().y() - restHeight);
			}
			energy[mode] = e;
			peak[mode] = std::max(peak[mode], e);
		}
		text[mode] = "energy above rest " + fmt(energy[mode], "J", 2) + " of " + fmt(released, "J", 2) + " released, peak " + fmt(peak[mode], "J", 2);
	}
	printParity("Pendulum chain, 4 links, released horizontal, t = 2 s", text);

	ASSERT_GT(energy[Mode::Stock], 0.5 * released) << "stock Bullet loses most of the swing: the scene is wrong";
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		EXPECT_GE(energy[mode], kMinFraction * energy[Mode::Stock]) << "the chain loses its swing";
		EXPECT_LE(peak[mode], kMaxGain * released) << "the chain gains energy (joints and gravity add none)";
	}
}

// Chains of 2 and of 3 links hang still from static anchors, each joint with a btJointFeedback.
// Statics: a joint carries the weight of every link below it, so after settling (1 s) each
// joint's feedback force equals that weight within 10 %, in stock Bullet and in both plugin modes.
TEST(JointParity, JointFeedbackCarriesWeight)
{
	constexpr double kTolerance = 0.10;
	const int chainLengths[] = {2, 3};
	PerMode<double> worstError;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		Scene scene(mode);
		std::vector<Chain> chains;
		std::vector<std::unique_ptr<btJointFeedback>> feedback;
		for (int c = 0; c < 2; ++c)
		{
			chains.push_back(addChain(scene, chainLengths[c], vec(3.0 * c, 3, 0), vec(0, -1, 0)));
			for (btPoint2PointConstraint* joint : chains.back().joints)
			{
				feedback.emplace_back(new btJointFeedback());
				joint->setJointFeedback(feedback.back().get());
				joint->enableFeedback(true);
			}
		}
		for (int i = 0; i < scene.stepsFor(1.0); ++i) scene.step();

		std::string t;
		size_t f = 0;
		for (int c = 0; c < 2; ++c)
		{
			t += (c ? "; " : "") + std::to_string(chainLengths[c]) + " links:";
			for (int j = 0; j < chainLengths[c]; ++j, ++f)
			{
				// Joint j holds links j .. n-1: on the link below it (body A) it pushes up with their weight.
				const double carried = (chainLengths[c] - j) * kLinkMass * kGravity;
				const double force = feedback[f]->m_appliedForceBodyA.length();
				worstError[mode] = std::max(worstError[mode], std::fabs(force - carried) / carried);
				t += " " + fmt(force, "", 2) + "/" + fmt(carried, "", 2);
			}
		}
		text[mode] = t + " N (feedback/weight), worst " + fmt(100 * worstError[mode], "%", 1);
	}
	printParity("Joint feedback, hanging chains of 2 and 3 links, t = 1 s", text);

	for (Mode mode : kModes)
	{
		SCOPED_TRACE(modeName(mode));
		EXPECT_LE(worstError[mode], kTolerance) << "a joint's feedback force is not the weight it carries";
	}
}

// A link hangs from a static anchor by a joint whose breaking threshold is 75 % of the impulse of
// two links' weight per step: it holds one link. At 0.5 s a second link is attached below it; the
// load doubles and the joint must break on the same step as under stock Bullet (within 1 step).
TEST(JointParity, BreakingThresholdBreaksOnSameStep)
{
	constexpr int kAttachStep = 30;
	PerMode<int> brokeAt;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		Scene scene(mode);
		const btVector3 anchor = vec(0, 3, 0);
		Chain chain = addChain(scene, 1, anchor, vec(0, -1, 0));
		btPoint2PointConstraint* top = chain.joints[0];
		top->setBreakingImpulseThreshold(btScalar(0.75 * 2 * kLinkMass * kGravity * scene.timeStep()));
		brokeAt[mode] = -1;
		for (int i = 0; i < scene.stepsFor(1.5) && brokeAt[mode] < 0; ++i)
		{
			if (scene.steps() == kAttachStep)
			{
				// The second link hangs below the first, already in place.
				const btQuaternion down(btVector3(0, 0, 1), btScalar(-kPi / 2));
				btRigidBody* second = scene.addBody(new btBoxShape(vec(kLinkHalf, 0.05, 0.05)), kLinkMass,
													btTransform(down, anchor - vec(0, 3 * kLinkHalf, 0)), false, kNoCollisionGroup, 0);
				scene.addConstraint(new btPoint2PointConstraint(*chain.links[0], *second, vec(kLinkHalf, 0, 0), vec(-kLinkHalf, 0, 0)));
			}
			scene.step();
			if (!top->isEnabled()) brokeAt[mode] = scene.steps();
		}
		text[mode] = brokeAt[mode] < 0 ? std::string("did not break") : "broke at step " + std::to_string(brokeAt[mode]) + " (attached after step " + std::to_string(kAttachStep) + ")";
	}
	printParity("Breakable joint, threshold 0.75 of 2-link load, second link at 0.5 s", text);

	ASSERT_GT(brokeAt[Mode::Stock], kAttachStep) << "stock Bullet breaks the joint before the load arrives: the scene is wrong";
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		EXPECT_GT(brokeAt[mode], 0) << "the joint never broke";
		EXPECT_LE(std::abs(brokeAt[mode] - brokeAt[Mode::Stock]), 1) << "broke on another step than under stock";
	}
}

// A car: a 1.6 x 0.2 x 1 m chassis (10 kg) resting only on 4 sphere wheels (r 0.3 m, 1 kg) joined
// by btHingeConstraint with angular motors (target 5 rad/s, so 1.5 m/s rolling, max impulse
// 1 N s per step) drives on the ground for 3 s. The motors hold the wheels at their target speed,
// so the speed settles: its mean over the last second equals stock's within 10 %, and the chassis
// pitches no more than under stock + 1 degree.
TEST(JointParity, HingeMotorCarDrives)
{
	constexpr double kWheelRadius = 0.3;
	constexpr double kWheelSpeed = 5.0;	 // rad/s
	constexpr double kSeconds = 3.0;
	PerMode<double> speed;
	PerMode<double> pitch;
	PerMode<std::string> text;
	for (Mode mode : kModes)
	{
		Scene scene(mode);
		scene.addGround();
		const double chassisHeight = kWheelRadius - kOverlap + 0.2;	 // hinge pivots 0.2 m below the chassis centre
		btRigidBody* chassis = scene.addBox(vec(0.8, 0.1, 0.5), 10.0, vec(0, chassisHeight, 0));
		for (int i = 0; i < 4; ++i)
		{
			const btVector3 pivot = vec(i < 2 ? 0.7 : -0.7, -0.2, i % 2 ? 0.7 : -0.7);
			btRigidBody* wheel = scene.addSphere(kWheelRadius, 1.0, vec(0, chassisHeight, 0) + pivot);
			wheel->setFriction(btScalar(1));
			// Wheels turn about the chassis' z axis; the hinge's positive motor direction rolls
			// the car towards +x (a wheel's turn relative to the chassis, as Bullet counts it).
			btHingeConstraint* hinge = new btHingeConstraint(*chassis, *wheel, pivot, vec(0, 0, 0), vec(0, 0, 1), vec(0, 0, 1));
			hinge->enableAngularMotor(true, btScalar(kWheelSpeed), btScalar(1.0));
			scene.addConstraint(hinge);
		}
		double sum = 0;
		int samples = 0;
		double maxPitch = 0;
		for (int i = 0; i < scene.stepsFor(kSeconds); ++i)
		{
			scene.step();
			// Pitch: angle of the chassis' forward (x) axis above the horizontal.
			const btVector3 forward = chassis->getWorldTransform().getBasis().getColumn(0);
			maxPitch = std::max(maxPitch, std::fabs(std::asin(std::max(-1.0, std::min(1.0, double(forward.y()))))));
			if (scene.time() > kSeconds - 1.0 + 1e-9)
			{
				sum += chassis->getLinearVelocity().x();
				++samples;
			}
		}
		speed[mode] = sum / samples;
		pitch[mode] = maxPitch * 180 / kPi;
		text[mode] = "last-second speed " + fmt(speed[mode], "m/s") + ", max pitch " + fmt(pitch[mode], "deg", 2);
	}
	printParity("Hinge-motor car, 4 wheels, 3 s", text);

	ASSERT_GT(speed[Mode::Stock], 0.5 * kWheelSpeed * kWheelRadius) << "stock Bullet's car does not drive: the scene is wrong";
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		EXPECT_NEAR(speed[mode], speed[Mode::Stock], 0.10 * speed[Mode::Stock]) << "cruising speed";
		EXPECT_LE(pitch[mode], pitch[Mode::Stock] + 1.0) << "chassis pitch (degrees)";
	}
}

namespace
{
/// Runs a 0.2 m cube (1 kg) free to move 0.5 m down from its start, held by a constraint that
/// addLimited builds, with a 0.3 m, 5 kg load resting on it (so the limit holds a 2-high stack);
/// returns how far past the limit the cube is at 2 s (m, negative = short of it).
double limitViolation(Mode mode, void (*addLimited)(Scene&, btRigidBody&, double))
{
	constexpr double kTravel = 0.5;
	Scene scene(mode);
	const btVector3 start = vec(0, 3, 0);
	btRigidBody* body = scene.addBody(new btBoxShape(vec(0.1, 0.1, 0.1)), 1.0, btTransform(btQuaternion::getIdentity(), start));
	scene.addBox(vec(0.15, 0.15, 0.15), 5.0, start + vec(0, 0.25 - kOverlap, 0));
	addLimited(scene, *body, kTravel);
	for (int i = 0; i < scene.stepsFor(2.0); ++i) scene.step();
	return (start.y() - body->getCenterOfMassPosition().y()) - kTravel;
}

/// A slider whose axis (its frame's x axis) points down, free over [0, travel], rotation locked.
void addSlider(Scene& scene, btRigidBody& body, double travel)
{
	const btTransform frame(btQuaternion(btVector3(0, 0, 1), btScalar(-kPi / 2)), btVector3(0, 0, 0));
	btSliderConstraint* slider = new btSliderConstraint(body, frame, true);
	slider->setLowerLinLimit(btScalar(0));
	slider->setUpperLinLimit(btScalar(travel));
	scene.addConstraint(slider);
}

/// A 6-dof spring2 constraint with y free over [-travel, 0] and everything else locked.
void addSixDof(Scene& scene, btRigidBody& body, double travel)
{
	btGeneric6DofSpring2Constraint* dof = new btGeneric6DofSpring2Constraint(body, btTransform::getIdentity());
	dof->setLinearLowerLimit(vec(0, -travel, 0));
	dof->setLinearUpperLimit(vec(0, 0, 0));
	dof->setAngularLowerLimit(vec(0, 0, 0));
	dof->setAngularUpperLimit(vec(0, 0, 0));
	scene.addConstraint(dof);
}

void checkLimit(const char* name, const PerMode<double>& violation)
{
	PerMode<std::string> text;
	for (Mode mode : kModes) text[mode] = "limit violation " + fmt(violation[mode] * 1000, "mm", 2);
	printParity(name, text);
	// Stock must hold the body near its limit (within 5 cm either way) for the scene to mean anything.
	ASSERT_LT(std::fabs(violation[Mode::Stock]), 0.05) << "stock Bullet does not bring the body to its limit: the scene is wrong";
	for (Mode mode : kPluginModes)
	{
		SCOPED_TRACE(modeName(mode));
		EXPECT_LE(violation[mode], violation[Mode::Stock] + 0.001) << "the body sinks past its limit";
	}
}
}  // namespace

// A slider (axis pointing down, rotation locked) lets a cube carrying a load fall 0.5 m onto its
// upper linear limit and hold there under gravity; the final violation of the limit is no more
// than stock's + 1 mm.
TEST(JointParity, SliderLimitHolds)
{
	PerMode<double> violation;
	for (Mode mode : kModes)
	{
		violation[mode] = limitViolation(mode, addSlider);
	}
	checkLimit("Slider linear limit, loaded cube falls 0.5 m onto it, t = 2 s", violation);
}

// A btGeneric6DofSpring2Constraint (angles locked, y free over [-0.5, 0] m) lets a cube carrying
// a load fall onto its lower linear limit and hold there; the final violation is no more than
// stock's + 1 mm.
TEST(JointParity, SixDofSpring2LimitHolds)
{
	PerMode<double> violation;
	for (Mode mode : kModes)
	{
		violation[mode] = limitViolation(mode, addSixDof);
	}
	checkLimit("6-dof spring2 linear limit, loaded cube falls 0.5 m onto it, t = 2 s", violation);
}
}  // namespace parity
