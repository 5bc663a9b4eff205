/*
BulletShockPropagation - velocity-based shock propagation for Bullet
Copyright (c) 2026 the BulletShockPropagation authors

This software is provided 'as-is', without any express or implied warranty.
In no event will the authors be held liable for any damages arising from the use of this software.
Permission is granted to anyone to use this software for any purpose,
including commercial applications, and to alter it and redistribute it freely,
subject to the following restrictions:
1. The origin of this software must not be misrepresented; you must not claim that you wrote the original software. If you use this software in a product, an acknowledgment in the product documentation would be appreciated but is not required.
2. Altered source versions must be plainly marked as such, and must not be misrepresented as being the original software.
3. This notice may not be removed or altered from any source distribution.
*/

#ifndef BT_SHOCK_PROPAGATION_SHOCK_PREDICTOR_H
#define BT_SHOCK_PROPAGATION_SHOCK_PREDICTOR_H

#include "BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h"
#include "LinearMath/btMatrix3x3.h"

#include "btCholesky6.h"
#include "BulletShockPropagation/btShockPropagationSettings.h"

class btStackLayers;

/// The predictor stage of the velocity step: shock propagation (Erleben 2007) with weight
/// feeling (in the spirit of Xiong et al. 2025), as an order of row updates whose impulses are
/// all, in the end, applied to both bodies of their row. Private to the plugin.
///
/// Rows are Bullet's, set up once for the step (contact normals, friction, rolling friction).
/// Row i couples bodies A and B with Jacobians J_A, J_B and effective-mass terms
///   D_A = J_A W_A J_A^T,  D_B = J_B W_B J_B^T,  Bullet's m_jacDiagABInv = r / (D_A + D_B + c),
/// (r the row's relaxation, c its constraint force mixing). Bullet's update of the row,
///   dL = m_rhs - L m_cfm - m_jacDiagABInv (J_A dv_A + J_B dv_B),
/// is the projected Gauss-Seidel step of the coupled problem. With B fixated (infinite mass,
/// "fixate bottom-most objects of layer") the same row's exact step for A alone is
///   dL' = s dL,   s = (D_A + D_B + c) / (D_A + c),
/// applied to A only; B's share, dL' times its Jacobian, is *withheld* (kept per row) and applied
/// to B later. Nothing is lost: once every withheld impulse is delivered, every row's impulse has
/// acted on both bodies, so momentum and angular momentum change only through rows to static or
/// kinematic bodies and external forces (Newton's third law holds for the whole pass).
///
/// Layer k holds the rows of the graph edges whose upper end has height k + 1 (btStackLayers);
/// its lower ends (height <= k) are fixated in it.
///   up pass    k = 0 .. K-1: sweep layer k, lower ends fixated, until converged;
///   down pass  k = K-1 .. 0 (weight feeling): sweep layer k again (its bodies now carry what was
///              delivered to them from above), then deliver its withheld impulses to the bodies
///              below; without weight feeling every withheld impulse is delivered after the up
///              pass (the classic method, which then leaves the rest to the corrector).
/// Within a layer's sweeps a row is swept again only while one of its bodies moved in the last
/// sweep (a change beyond the convergence speed), so a converged body costs nothing while its
/// neighbours still move.
/// For a column this is the exact block elimination of the contact problem: the up pass gives
/// each body its own weight, the down pass hands each body the reactions of those above.
///
/// Cycles. Where the layers couple (a body on several supports, a pyramid), one up-and-down
/// cycle leaves each layer fitted to supports that the layers below moved afterwards; the next
/// cycle starts from the last one's velocities. Cycles end once the coupled residual, with every
/// impulse delivered,
///   r = max over rows of |(m_rhs - L m_cfm) / m_jacDiagABInv - (J_A v_A + J_B v_B)|,
/// counting only rows whose impulse L could still move that way (below its upper bound for a
/// positive error, above its lower bound for a negative one; a friction or rolling row's bounds
/// are those its sweep sets, rowBounds), is at most the convergence speed: then no PGS step of the coupled
/// problem would change a velocity by more than a layer's own sweeps were allowed to leave.
/// With weight feeling they also end once a cycle does not lower r (the first cycle: below r
/// before the passes), and from the second cycle once no layer needs a second sweep (its down
/// pass has met every reaction delivered) or once the cycles left, each lowering r by the last
/// one's ratio, cannot bring it to the convergence speed: in a pile the first cycle leaves r at
/// 0.1-3 m/s, most often above its value before the passes (median 2.3 times), and each further
/// cycle is another sweep of every layer that the search mostly discards; in a resting stack the
/// first cycle lowers r 3e4 to 1e6 times. A cycle after the first is an inexact solve: its layer visits end at
/// max(convergence speed, forcing r_last) (forcing 0.01), as an inexact Newton method solves its
/// inner systems only as far as the outer error warrants. At 0.1 the column tipping over a ledge
/// turns 11-13% faster than rigid-body dynamics says; at 0.01, 4% (exact visits: 3%). The
/// classic order (no down pass) delivers each cycle's reactions after its up pass and meets them
/// only in the next cycle, so neither a cycle of one-sweep layers nor one whose residual rises
/// says anything there; a load reaches the ground one layer per cycle and the ground's answer the
/// top one layer per cycle, so the classic order runs up to max(cycles, 2 K) cycles, ended by the
/// residual alone (K layers).
///
/// Line search. Where fixation is wrong (a support that slides) the passes' change is not the
/// coupled problem's answer, and taken whole it can add energy: on ice the up pass drags every
/// body to the bottom one's velocity and the delivered reactions hand the bottom body (carried
/// mass / its mass) times its error. Each cycle moves the bodies' velocities from u to u + du;
/// along u + alpha du the kinetic energy is E(0) + alpha du.M u + alpha^2/2 du.M du, and the
/// predictor takes alpha = clamp(-du.M u / du.M du, 0, 1) for each contact-graph component on
/// its own (a ball's rebound, which no minimum of E keeps, then does not shorten the step of a
/// tower solved in the same group), scaling the impulse changes alike: contact impulses are
/// passive, and Newton's third law holds for any alpha. The search follows every cycle, and the
/// next cycle starts from its result: two sticking boxes on ice, relative velocity e, leave a
/// cycle at -(m_top / m_bottom) e (the bottom box is handed the top one's whole correction), so
/// unsearched cycles diverge by that ratio each (a pyramid of base 20 in float: 1e-6, 3.4e-6,
/// 1.2e-4 m/s), while the search takes alpha = m_bottom / (m_bottom + m_top), where the two move
/// together. A search that keeps nothing ends the cycles. (PGS's own objective
/// is no measure here: with Coulomb friction its bounds move with the normal impulses, and a
/// search on it stopped a resting tower's predictor; docs/history.md, section 4u.)
class btShockPredictor
{
public:
	struct Pools
	{
		btAlignedObjectArray<btSolverBody>& m_bodies;
		btConstraintArray& m_contacts;
		btConstraintArray& m_frictions;
		btConstraintArray& m_rollingFrictions;
	};

	/// Bucket the rows by layer. contactRowLayer: layer of each contact row (-1: in no layer);
	/// heightOfSolverBody: stack height of each solver body (0: static or kinematic, -1: in a
	/// component without a root, never fixated); componentOfSolverBody: its contact-graph
	/// component (0 .. numComponents - 1; -1: static or kinematic), each searched on its own.
	void build(const Pools& pools, int numLayers, const btAlignedObjectArray<int>& contactRowLayer,
			   const btAlignedObjectArray<int>& heightOfSolverBody, const btAlignedObjectArray<int>& componentOfSolverBody,
			   int numComponents);

	/// Up pass then down pass (or delivery); at most sweeps per layer and pass, a layer ends once
	/// a sweep changes no row's velocity by more than convergedSpeed (m/s) in the first cycle, by
	/// more than max(convergedSpeed, forcing times the last cycle's coupled residual) in later
	/// ones. Returns sweeps run.
	int predict(const Pools& pools, int sweeps, btScalar convergedSpeed, bool weightFeeling, int cycles, btScalar forcing);

	int getNumLayers() const { return m_numLayers; }

	/// Start each contact row past the fixation limit (maxFixationScale; solved with both bodies
	/// free, as Bullet solves it) from its point's last impulse times factor, applied to both
	/// bodies, as a stock step starts it: from zero a few sweeps cannot carry a heavy body through
	/// a light one (609 t on 83 g: its velocity fell as g t while the position correction held it
	/// up, docs/design.md, section 4.3); the warm start carries the load from step to step.
	void warmStartPastLimit(const Pools& pools, btScalar factor);

	/// Largest s at which a row's lower body is fixated: 1 / sqrt(FLT_EPSILON) = 2.9e3, in float and
	/// double alike. The fixated body's velocity carries s times the free one's change until its own
	/// supports take it back, so whatever the free body's visit left (up to the convergence speed
	/// per sweep, and the rounding) reaches it multiplied by s. The limit was once 1 / sqrt(epsilon)
	/// of the build's precision (6.7e7 in double): there a 0.6 kg box under a 3.6 t one, on a 5 g
	/// box, was fixated and the 5 g box thrown at 51 m/s, and hostile worlds without poison went
	/// over their bounds in 41 of 1,000 seeds (the fastest body 2,874 times the speed cap) against
	/// 9 at 2.9e3 (stock 7; docs/design.md, section 4.3). A row with a larger s is solved with both
	/// bodies free, as Bullet does, in the velocity step and in the position correction alike.
	static btScalar maxFixationScale() { return btScalar(1) / btSqrt(btScalar(FLT_EPSILON)); }
	/// s = total / freeTerm of a row whose lower side would be fixated (total = D_A + D_B + c,
	/// freeTerm = D_free + c), or 0 where no impulse can move the free side (freeTerm is 0: a
	/// zero-mass axis, the row has nothing to solve). The side is fixated where s <=
	/// maxFixationScale(). A free side that moves, however little, is no zero-mass axis: a 1e7 kg
	/// box on a 1 kg one (s = 1e7 + 1) was once taken for one, its row skipped by the predictor
	/// and its position fixated, and the box's velocity fell as g t while its position held
	/// (1.1e8 J from nothing in 2 s; docs/design.md, section 4.3).
	static btScalar fixationScale(btScalar freeTerm, btScalar total) { return freeTerm > btScalar(0) ? total / freeTerm : btScalar(0); }

private:
	enum Kind
	{
		CONTACT,
		FRICTION,
		ROLLING
	};
	struct Row
	{
		btSolverConstraint* m_row;
		const btSolverConstraint* m_normal;  // friction rows: the contact row bounding them
		btScalar m_scale;                     // s above; 1 when no side is fixated
		btScalar m_withheld;                  // impulse not yet applied to the fixated side (N s)
		btScalar m_start;                     // impulse before the passes (N s)
		btScalar m_total;                     // D_A + D_B + c of the row
		btScalar m_layerDelta;                // composite rows: impulse change not yet applied to the free body
		btScalar m_restTarget;                // impulse-scaled motion of a resting fixated side, hidden in its layer's visit (N s)
		btScalar m_fixedTerm;                 // J_B W' J_B^T of a mobile fixated side (btFixatedMobility.cpp), else 0
		int m_free;                           // the free side's solver body, -1 if no side is fixated
		// The row's solver bodies (m_solverBodyIdA, m_solverBodyIdB), kept here: a sweep's test of a
		// row that did not move and the fixated side's lookups then read no constraint. The row
		// keeps its size (64 bytes in float, 88 in double): kind and side fit in a byte.
		int m_bodyA, m_bodyB;
		bool m_pastLimit;                     // a one-sided row whose s exceeds maxFixationScale, solved both free
		signed char m_kind;
		signed char m_fixed;  // 0: none, 1: A, 2: B
	};

	/// Apply an impulse to one side of a row as Bullet's kernels do (sideA: body A with its
	/// Jacobian, else body B with its own).
	static void applyToSide(const btSolverConstraint& c, bool sideA, btScalar impulse, btAlignedObjectArray<btSolverBody>& bodies)
	{
		btSolverBody& body = bodies[sideA ? c.m_solverBodyIdA : c.m_solverBodyIdB];
		body.internalApplyImpulse((sideA ? c.m_contactNormal1 : c.m_contactNormal2) * body.internalGetInvMass(),
								  sideA ? c.m_angularComponentA : c.m_angularComponentB, impulse);
	}
	/// The velocity change of one side of a row along its Jacobian (Bullet's delta form).
	static btScalar sideVelocity(const btSolverConstraint& c, bool sideA, btAlignedObjectArray<btSolverBody>& bodies)
	{
		btSolverBody& body = bodies[sideA ? c.m_solverBodyIdA : c.m_solverBodyIdB];
		return (sideA ? c.m_contactNormal1 : c.m_contactNormal2).dot(body.internalGetDeltaLinearVelocity()) +
			   (sideA ? c.m_relpos1CrossNormal : c.m_relpos2CrossNormal).dot(body.internalGetDeltaAngularVelocity());
	}
	/// J_A (vA, wA) + J_B (vB, wB): a row's velocity from its bodies' linear and angular
	/// velocities (whole, delta or a change), summed term by term, A then B, as Bullet's kernel
	/// does (sideVelocity(A) + sideVelocity(B) rounds differently, and the pushed stack's truth
	/// turns on that rounding; docs/history.md, section 4u).
	static btScalar rowVelocity(const btSolverConstraint& c, const btVector3& vA, const btVector3& wA, const btVector3& vB, const btVector3& wB)
	{
		return c.m_contactNormal1.dot(vA) + c.m_relpos1CrossNormal.dot(wA) + c.m_contactNormal2.dot(vB) + c.m_relpos2CrossNormal.dot(wB);
	}
	/// A body's whole velocity (Bullet keeps it as the step's start, the external impulse and the
	/// solver's delta).
	static btVector3 wholeLinear(btSolverBody& body)
	{
		return body.m_linearVelocity + body.m_externalForceImpulse + body.internalGetDeltaLinearVelocity();
	}
	static btVector3 wholeAngular(btSolverBody& body)
	{
		return body.m_angularVelocity + body.m_externalTorqueImpulse + body.internalGetDeltaAngularVelocity();
	}
	/// A row that is solved with both bodies free, as Bullet's own.
	static void freeBothSides(Row& r)
	{
		r.m_fixed = 0;
		r.m_fixedTerm = 0;
		r.m_free = -1;
		r.m_scale = 1;
	}
	/// The free side's Jacobian of a one-sided row (linear, angular about the free body's centre).
	static void freeSide(const Row& r, btVector3& n, btVector3& cr)
	{
		const bool freeIsA = r.m_fixed == 2;
		n = freeIsA ? r.m_row->m_contactNormal1 : r.m_row->m_contactNormal2;
		cr = freeIsA ? r.m_row->m_relpos1CrossNormal : r.m_row->m_relpos2CrossNormal;
	}
	/// Friction and rolling rows: their bounds from their contact's impulse, as a stock sweep sets
	/// them, and 0 once the contact stops pushing (Bullet's sweep skips such a row instead and
	/// would leave its impulse in place). Other rows keep theirs.
	static void rowBounds(const Row& r, btScalar& lower, btScalar& upper)
	{
		const btSolverConstraint& c = *r.m_row;
		if (!r.m_normal)
		{
			lower = c.m_lowerLimit;
			upper = c.m_upperLimit;
			return;
		}
		const btScalar normal = btMax(btScalar(0), r.m_normal->m_appliedImpulse);
		upper = r.m_kind == FRICTION ? c.m_friction * normal : btMin(c.m_friction * normal, c.m_friction);
		lower = -upper;
	}
	static void boundByNormal(Row& r) { rowBounds(r, r.m_row->m_lowerLimit, r.m_row->m_upperLimit); }
	int sweepLayer(int layer, const Pools& pools, int sweeps, btScalar convergedSpeed, bool composites);
	void showRestingSupports(int layer, btAlignedObjectArray<btSolverBody>& bodies, btScalar restSpeed);
	int sweepRows(int layer, const Pools& pools, int sweeps, btScalar convergedSpeed, bool composites);
	bool heldBySupports(int body, btAlignedObjectArray<btSolverBody>& bodies, btScalar speed);
	/// Jacobi-scaled pivot above which a direction counts as spanned by a body's rows
	/// (btShockPropagationNumerics).
	static btScalar spanMinPivot() { return btShockPropagationNumerics::spanMinPivot(); }
	// A fixated body's mobility W' (btFixatedMobility.cpp): the inverse mass left in the
	// directions its supports do not resist, in linear-linear, linear-angular and angular-angular
	// blocks; m_mobile: per solver body, its entry in m_mobility, -1 where W' = 0.
	struct Mobility
	{
		Mobility() : m_vv(0, 0, 0, 0, 0, 0, 0, 0, 0), m_vw(0, 0, 0, 0, 0, 0, 0, 0, 0), m_ww(0, 0, 0, 0, 0, 0, 0, 0, 0) {}
		btMatrix3x3 m_vv, m_vw, m_ww;
	};
	btAlignedObjectArray<int> m_mobile;
	btAlignedObjectArray<Mobility> m_mobility;
	/// A direction of a body's support rows (its side's Jacobian), made W-orthonormal.
	struct SupportDirection
	{
		btVector3 m_linear, m_angular;
	};
	/// W-orthonormal basis (h_k^T W h_j = delta_jk, W = diag(invMass I, invInertia)) of the body's
	/// one-sided support rows' Jacobians, by Gram-Schmidt in row order: a row is kept if its norm
	/// left after the projections is above spanMinPivot() of its own. With resistingOnly, friction
	/// and rolling rows whose coefficient is 0 are skipped (they cannot resist). Returns the rank;
	/// oneSided says whether any support row is one-sided.
	int supportBasis(int body, btScalar invMass, const btMatrix3x3& invInertia, bool resistingOnly, SupportDirection basis[6], bool& oneSided) const;
	void formMobility(const btAlignedObjectArray<btSolverBody>& bodies);
	void mobileResponse(const Row& r, btScalar impulse, btVector3& dv, btVector3& dw) const;
	/// Moves a row's mobile fixated side by W' J^T (sign impulse): at once as the row changes
	/// (sign 1), taken back from a delivery of the whole withheld impulse (sign -1).
	void moveFixated(const Row& r, btScalar impulse, btScalar sign, btAlignedObjectArray<btSolverBody>& bodies) const
	{
		if (impulse != btScalar(0) && mobileFixated(r)) moveMobile(r, impulse * sign, bodies);
	}
	void moveMobile(const Row& r, btScalar impulse, btAlignedObjectArray<btSolverBody>& bodies) const;
	/// Whether the row's fixated side is mobile. Without any mobile body (most steps) m_mobile is
	/// all -1, so the lookup is skipped.
	bool mobileFixated(const Row& r) const { return r.m_fixed && m_mobility.size() && m_mobile.size() && m_mobile[fixedSide(r)] >= 0; }
	/// The factor of the body's one-sided support rows (held in m_spanFactors), 0 where they do not
	/// span the six directions.
	const btCholesky6* supportFactor(int body) const;
	// supportFactor's result per solver body for the step: 0 not yet formed, 1 spans
	// (m_spanFactors holds the factor), 2 does not. Grounding forms it once a body's support rows
	// are final (the rows to bodies that are not grounded freed first); a body whose rows it frees
	// afterwards (not grounded, alone or in its cluster) did not span and spans less.
	mutable btAlignedObjectArray<char> m_spanState;
	mutable btAlignedObjectArray<btCholesky6> m_spanFactors;
	// Per solver body: the support rows its span factor holds (its one-sided rows as it was formed).
	mutable btAlignedObjectArray<int> m_spanRowCount;
	mutable btCholesky6 m_spanScratch;  // a body's factor outside the step's arrays
	// Per solver body: the lower triangle of sum J_r J_r^T over the rows addRow made one-sided with
	// it free (21 entries, row by row), and how many; supportFactor takes them while none of those
	// rows has been freed since (a pass over the constraints fewer).
	btAlignedObjectArray<btScalar> m_supportSums;
	btAlignedObjectArray<int> m_supportSumRows;
	int addSupportRows(int body, btScalar* A, int stride, int offset) const;
	static int fixedSide(const Row& r) { return r.m_fixed == 1 ? r.m_bodyA : r.m_bodyB; }
	/// updateRow, returning the row's velocity change (m/s).
	btScalar solveRow(Row& row, btAlignedObjectArray<btSolverBody>& bodies);
	/// One projected update of a row (one-sided where a side is fixated); returns its impulse change.
	btScalar updateRow(Row& row, btAlignedObjectArray<btSolverBody>& bodies);
	void deliver(int layer, btAlignedObjectArray<btSolverBody>& bodies);
	/// The coupled residual r of the cycles (m/s); every impulse must have been delivered. Records
	/// each row's impulse as the start of the next cycle (recordStart) in the same pass.
	btScalar residual(const btAlignedObjectArray<btSolverBody>& bodies);
	/// Whether cyclesLeft more cycles, each lowering the residual by r / last, reach convergedSpeed.
	static bool reachable(btScalar r, btScalar last, btScalar convergedSpeed, int cyclesLeft);
	void addRow(btSolverConstraint& c, const btSolverConstraint* normal, int kind, int layer, const btAlignedObjectArray<btSolverBody>& bodies,
				const btAlignedObjectArray<int>& heightOfSolverBody);

	/// A dynamic body's world inertia I (the inverse of its inverse inertia tensor), or 0 where that
	/// tensor is singular (|det| not above SIMD_EPSILON). The tensor is the step's, so the inverse
	/// is formed once per body and step (the support blocks, the line search and the composites each
	/// asked for it again).
	const btMatrix3x3* worldInertia(int body, const btRigidBody& rb) const;
	mutable btAlignedObjectArray<char> m_inertiaState;  // per solver body: 0 not formed, 1 m_inertia holds it, 2 singular
	mutable btAlignedObjectArray<btMatrix3x3> m_inertia;
	mutable btMatrix3x3 m_inertiaScratch;

	/// The bodies' velocities before a cycle's passes (the rows' impulses: residual, just before).
	void recordStart(btAlignedObjectArray<btSolverBody>& bodies);
	btScalar lineSearch(btAlignedObjectArray<btSolverBody>& bodies);

	int m_numLayers = 0;
	btScalar m_visitSpeed = 0;  // m/s: a layer visit ends once a sweep changes no row by more than this (predict)
	const btAlignedObjectArray<int>* m_componentOfSolverBody = 0;
	btAlignedObjectArray<btScalar> m_slope, m_curvature, m_alpha;  // line search, per component
	btAlignedObjectArray<btVector3> m_startLinear, m_startAngular;  // per solver body, before the passes
	/// A solver body's record in a layer's sweeps (sweepRows), kept together: a row's test and update
	/// of its bodies' records then touch one place per body instead of one per array.
	struct SweepBody
	{
		SweepBody() : m_linear(0, 0, 0), m_angular(0, 0, 0), m_diffLinear(0, 0, 0), m_diffAngular(0, 0, 0), m_diffAt(0), m_movedAt(0) {}
		btVector3 m_linear, m_angular;          // its velocity before the current sweep
		btVector3 m_diffLinear, m_diffAngular;  // its change over the sweep
		unsigned m_diffAt;                      // the sweep (m_stamp) whose change it holds
		unsigned m_movedAt;                     // the last sweep (m_stamp) whose change moved it
	};
	btAlignedObjectArray<SweepBody> m_sweepBodies;  // per solver body
	btAlignedObjectArray<char> m_rowActive;    // per row of the layer being swept: swept in the current sweep
	unsigned m_stamp = 0;
	btAlignedObjectArray<btScalar> m_sweepChange;  // per sweep of the current layer: its largest row velocity change (m/s)
	btAlignedObjectArray<btScalar> m_weldChange;   // per weld sweep (settleWelds): the same
	/// Records a sweep's largest change (m/s); true once the sweeps cannot reach convergedSpeed
	/// within sweeps at their rate (or their rate is 1: no solution).
	static bool cannotConverge(btAlignedObjectArray<btScalar>& changes, int sweep, btScalar largest, btScalar convergedSpeed, int sweeps);
	btAlignedObjectArray<Row> m_rows;        // by layer
	btAlignedObjectArray<int> m_layerStart;  // m_numLayers + 1 offsets into m_rows
	btAlignedObjectArray<int> m_count, m_cursor;

	// Welded composites (btWeldedComposites.cpp): in the down pass a free body carries the
	// inertia of the bodies welded to it above (their rows to it active at three or more points).
	struct Composite
	{
		Composite()
			: m_center(0, 0, 0), m_invMass(0), m_invInertia(0, 0, 0, 0, 0, 0, 0, 0, 0), m_v0(0, 0, 0), m_w0(0, 0, 0), m_rootDv0(0, 0, 0), m_rootDw0(0, 0, 0), m_dv(0, 0, 0), m_dw(0, 0, 0), m_sweepDv(0, 0, 0), m_sweepDw(0, 0, 0), m_root(-1), m_first(0), m_end(0)
		{
		}
		btVector3 m_center;
		btScalar m_invMass;
		btMatrix3x3 m_invInertia;
		btVector3 m_v0, m_w0;          // rigid velocity of the members' momentum as the layer begins
		btVector3 m_rootDv0, m_rootDw0;  // the root's solver-body delta that rigid velocity means
		btVector3 m_dv, m_dw;          // rigid velocity change of the composite this layer
		btVector3 m_sweepDv, m_sweepDw;  // the same at the start of the current sweep
		int m_root, m_first, m_end;    // members m_members[m_first, m_end), the root first
	};
	void bucketSupportRows(int numBodies);
	void groundRows(const btAlignedObjectArray<btSolverBody>& bodies, const btAlignedObjectArray<int>& heightOfSolverBody);
	btAlignedObjectArray<char> m_grounded;  // groundRows: per solver body, 0 undecided, 1 grounded, 2 not grounded
	// Clusters (groundRows): a layer's bodies not grounded alone, joined by the layer's rows among them.
	struct ClusterNode
	{
		int m_parent;      // union-find
		int m_index;       // position among its cluster's members
		int m_nextMember;  // members of a root, linked
		int m_firstMember;
		int m_firstRow;  // a root's rows among its members or to the layer's grounded bodies, linked by m_clusterRowNext
		int m_size;
	};
	int findCluster(int body);
	bool clusterSpans(int root);
	/// A body not grounded whose fixated support rows can still carry its own load (the force and
	/// torque on it: gravity and the app's): the part of that load outside their span is at most
	/// spanMinPivot() of it, in kinetic energy (a ball on one point, a capsule on its line).
	bool carriesOwnLoad(int body, const btSolverBody& solverBody) const;
	/// Whether the supports of a one-sided contact row's fixated body pass its push on: the push
	/// lies within one support's friction cone (or that support has no friction: mobility's part).
	bool pushCarried(const Row& r, const btAlignedObjectArray<btSolverBody>& bodies) const;
	btAlignedObjectArray<int> m_loose;  // groundRows: the layer's free bodies not grounded alone
	btAlignedObjectArray<const btSolverConstraint*> m_freedContacts;  // groundRows: a body's contact rows freed on both sides
	btAlignedObjectArray<ClusterNode> m_clusterNodes;
	btAlignedObjectArray<int> m_clusterRowNext;  // per row
	btAlignedObjectArray<btScalar> m_clusterMatrix;  // the cluster's 6 n x 6 n normal equations
	// Support blocks (btSupportBlocks.cpp): each free body's pushing support rows solved at once.
	void solveBlocks(int layer, const Pools& pools);
	void solveBlock(int body, btAlignedObjectArray<btSolverBody>& bodies);
	// Each body's block factor for the step (solveBlock): per body 0 none, 1 m_blockFactors holds
	// it, 2 no factor, 3 its span factor (m_spanFactors) is it; per support row slot
	// (m_supportRows), whether the last block held the row.
	btAlignedObjectArray<char> m_blockState, m_blockIncluded;
	btAlignedObjectArray<btCholesky6> m_blockFactors;
	btCholesky6 m_blockScratch;  // a composite's block factor (not kept)
	btAlignedObjectArray<int> m_blockRows;
	btAlignedObjectArray<const btSolverConstraint*> m_blockContacts;
	void findWelds(const Pools& pools);
	void formComposites(int layer, const Pools& pools, btScalar heldSpeed);
	btScalar solveCompositeRow(Row& row, Composite& composite, btAlignedObjectArray<btSolverBody>& bodies);
	btScalar compositeMotion(int layer, const btAlignedObjectArray<btSolverBody>& bodies) const;
	void finishComposites(int layer, const Pools& pools, int sweeps, btScalar convergedSpeed);
	void settleWelds(int sweeps, btScalar convergedSpeed, btAlignedObjectArray<btSolverBody>& bodies);
	const btCholesky6* weldFactor(int body) const;
	void applyToBoth(Row& row, btScalar impulse, btAlignedObjectArray<btSolverBody>& bodies);
	btAlignedObjectArray<int> m_supportStart, m_supportRows;  // per solver body: the rows where it is the free side
	btAlignedObjectArray<int> m_layerFreeStart, m_layerFree;  // per layer: its free bodies (bodies with support rows in it)
	btAlignedObjectArray<int> m_parent;                       // per solver body: the body it is welded to, -1
	btAlignedObjectArray<int> m_childStart, m_children;
	btAlignedObjectArray<int> m_compositeOf;                  // per solver body: its composite as root this layer, -1
	btAlignedObjectArray<Composite> m_composites;
	btAlignedObjectArray<int> m_members;
	btAlignedObjectArray<btVector3> m_weldForce, m_weldMoment;  // per solver body, back-substitution scratch
};

#endif  // BT_SHOCK_PROPAGATION_SHOCK_PREDICTOR_H
