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

#include "btLayeredPasses.h"

#include "btSupportBlock.h"
#include "btTippingComposite.h"

#include "BulletCollision/CollisionShapes/btCollisionShape.h"

#include "BulletCollision/NarrowPhaseCollision/btManifoldPoint.h"
#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"
#include "BulletDynamics/Dynamics/btRigidBody.h"
#include "BulletShockPropagation/btStackLayers.h"

#include <algorithm>
#include <functional>
#include <cstdint>

namespace
{
/// Counting sort of rows by layer into CSR arrays (start offsets of size K + 1, then rows).
void bucket(int numLayers, int numRows, const int* layerOfRow, btAlignedObjectArray<int>& start, btAlignedObjectArray<int>& rows,
			btAlignedObjectArray<int>& cursor)
{
	start.resize(numLayers + 1);
	for (int k = 0; k <= numLayers; ++k) start[k] = 0;
	for (int i = 0; i < numRows; ++i) ++start[layerOfRow[i] + 1];
	for (int k = 0; k < numLayers; ++k) start[k + 1] += start[k];
	rows.resize(numRows);
	cursor.resize(numLayers);
	for (int k = 0; k < numLayers; ++k) cursor[k] = start[k];
	for (int i = 0; i < numRows; ++i) rows[cursor[layerOfRow[i]]++] = i;
}

/// Keep the largest squared velocity change a row made in a sweep (Bullet's row kernels return the
/// change of the row's velocity, delta impulse / effective mass).
inline void noteResidual(btScalar& worst, btScalar residual)
{
	const btScalar r2 = residual * residual;
	if (r2 > worst) worst = r2;  // NaN (a row whose ends are both immovable: 0 / 0) is no change
}

/// D18: a point Bullet created this step (its lifetime starts at the step's refresh) that carries
/// no impulse yet.
bool isNewPoint(const btManifoldPoint& cp) { return cp.getLifeTime() <= 1 && cp.m_appliedImpulse == btScalar(0); }

btScalar totalNormalImpulse(const btPersistentManifold& m)
{
	btScalar total = 0;
	for (int j = 0; j < m.getNumContacts(); ++j) total += m.getContactPoint(j).m_appliedImpulse;
	return total;
}

int clampLayer(int layer, int numLayers)
{
	return (layer >= 0 && layer < numLayers) ? layer : 0;
}
}  // namespace

void btLayeredPasses::markDriven(const btSolverPools& pools)
{
	// D32: a body is driven if a joint holds it or a moving kinematic body touches it, and so is
	// every body it touches, through contacts between dynamic bodies: their slow motion comes from
	// the drive and is real. The rest of a group moves only by contacts and gravity.
	const int numBodies = pools.m_bodies.size();
	const int numContacts = pools.m_contacts.size();
	auto movable = [&](int id) {
		const btRigidBody* rb = pools.m_bodies[id].m_originalBody;
		return rb && rb->getInvMass() > btScalar(0);
	};
	m_driven.resize(numBodies);
	m_drivenQueue.resize(0);
	for (int i = 0; i < numBodies; ++i)
	{
		// Only dynamic bodies carry a drive on: a joint to the world also marks Bullet's shared
		// fixed body, which touches everything resting on static ground.
		m_driven[i] = m_jointed[i] && movable(i) ? 1 : 0;
		if (m_driven[i]) m_drivenQueue.push_back(i);
	}
	auto movingKinematic = [&](int id) {
		const btRigidBody* rb = pools.m_bodies[id].m_originalBody;
		return rb && rb->isKinematicObject() && (!rb->getLinearVelocity().fuzzyZero() || !rb->getAngularVelocity().fuzzyZero());
	};
	for (int i = 0; i < numContacts; ++i)
	{
		const int a = pools.m_contacts[i].m_solverBodyIdA;
		const int b = pools.m_contacts[i].m_solverBodyIdB;
		if (movingKinematic(a) && movable(b) && !m_driven[b]) m_driven[b] = 1, m_drivenQueue.push_back(b);
		if (movingKinematic(b) && movable(a) && !m_driven[a]) m_driven[a] = 1, m_drivenQueue.push_back(a);
	}
	if (m_drivenQueue.size() == 0) return;  // the usual case: nothing drives the group
	// Contacts of each body (both ends), bucketed.
	m_drivenStart.resize(numBodies + 1);
	for (int i = 0; i <= numBodies; ++i) m_drivenStart[i] = 0;
	for (int i = 0; i < numContacts; ++i)
	{
		++m_drivenStart[pools.m_contacts[i].m_solverBodyIdA + 1];
		++m_drivenStart[pools.m_contacts[i].m_solverBodyIdB + 1];
	}
	for (int i = 0; i < numBodies; ++i) m_drivenStart[i + 1] += m_drivenStart[i];
	m_drivenAdjacent.resize(m_drivenStart[numBodies]);
	m_scratchCursor.resize(numBodies);
	for (int i = 0; i < numBodies; ++i) m_scratchCursor[i] = m_drivenStart[i];
	for (int i = 0; i < numContacts; ++i)
	{
		const int a = pools.m_contacts[i].m_solverBodyIdA;
		const int b = pools.m_contacts[i].m_solverBodyIdB;
		m_drivenAdjacent[m_scratchCursor[a]++] = b;
		m_drivenAdjacent[m_scratchCursor[b]++] = a;
	}
	for (int head = 0; head < m_drivenQueue.size(); ++head)
	{
		const int id = m_drivenQueue[head];
		for (int k = m_drivenStart[id]; k < m_drivenStart[id + 1]; ++k)
		{
			const int other = m_drivenAdjacent[k];
			if (m_driven[other] || !movable(other)) continue;
			m_driven[other] = 1;
			m_drivenQueue.push_back(other);
		}
	}
}

void btLayeredPasses::build(const btStackLayers& layers, const btAlignedObjectArray<int>& contactRowLayer,
							const btAlignedObjectArray<int>& solverBodyOfNode, const btSolverPools& pools)
{
	m_layers = &layers;
	m_numLayers = btMax(1, layers.getNumLayers());
	btAlignedObjectArray<int>& layerOf = m_scratchLayer;
	const int numContacts = pools.m_contacts.size();
	layerOf.resize(numContacts);
	for (int i = 0; i < numContacts; ++i) layerOf[i] = clampLayer(contactRowLayer[i], m_numLayers);
	bucket(m_numLayers, numContacts, numContacts ? &layerOf[0] : 0, m_contactStart, m_contactRows, m_scratchCursor);
	m_pointCarried.resize(numContacts);
	m_pointFelt.resize(numContacts);
	for (int i = 0; i < numContacts; ++i)
	{
		const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(pools.m_contacts[i].m_originalContactPoint);
		m_pointCarried[i] = cp && cp->m_appliedImpulse > btScalar(0) ? 1 : 0;
		m_pointFelt[i] = cp ? btWithheldReactions::feltShare(*cp) : btScalar(0);
	}

	// Friction and rolling friction rows follow their contact row (m_frictionIndex).
	bucketFollowers(pools.m_frictions, layerOf, m_frictionStart, m_frictionRows);
	bucketFollowers(pools.m_rollingFrictions, layerOf, m_rollingStart, m_rollingRows);


	m_solverBodyOfNode = solverBodyOfNode;
	const int numSolverBodies = pools.m_bodies.size();
	m_nodeOfSolverBody.resize(numSolverBodies);
	m_fixated.resize(numSolverBodies);
	for (int i = 0; i < numSolverBodies; ++i)
	{
		m_nodeOfSolverBody[i] = -1;
		m_fixated[i] = 0;
	}
	for (int node = 0; node < solverBodyOfNode.size(); ++node)
	{
		const int id = solverBodyOfNode[node];
		if (id >= 0 && id < numSolverBodies) m_nodeOfSolverBody[id] = node;
	}
	// Support rows are gathered per layer on first use (gatherSupportRows).
	m_freeSlot.resize(m_numLayers + 1);
	m_freeSlot[0] = 0;
	for (int k = 0; k < m_numLayers; ++k) m_freeSlot[k + 1] = m_freeSlot[k] + (k < layers.getNumLayers() ? layers.getNumFreeBodies(k) : 0);
	m_supportBegin.resize(m_freeSlot[m_numLayers]);
	m_blockFactor.resize(m_freeSlot[m_numLayers]);
	m_blockFactorValid.resize(m_freeSlot[m_numLayers]);
	for (int i = 0; i < m_blockFactorValid.size(); ++i) m_blockFactorValid[i] = 0;
	m_supportEnd.resize(m_freeSlot[m_numLayers]);
	m_supportGathered.resize(m_numLayers);
	for (int k = 0; k < m_numLayers; ++k) m_supportGathered[k] = 0;
	m_slidUp.resize(pools.m_bodies.size());
	for (int i = 0; i < m_slidUp.size(); ++i) m_slidUp[i] = 0;
	// The bodies in a joint this step, from the step's joint rows: Bullet counts a body's
	// constraint refs only for joints added with disableCollisionsBetweenLinkedBodies, so
	// btRigidBody::getNumConstraintRefs() misses joints added as addConstraint(c) adds them.
	m_jointed.resize(pools.m_bodies.size());
	for (int i = 0; i < m_jointed.size(); ++i)
	{
		const btRigidBody* rb = pools.m_bodies[i].m_originalBody;
		m_jointed[i] = rb && rb->getNumConstraintRefs() > 0 ? 1 : 0;
	}
	for (int i = 0; i < pools.m_joints.size(); ++i)
	{
		const btSolverConstraint& c = pools.m_joints[i];
		if (c.m_solverBodyIdA >= 0 && c.m_solverBodyIdA < m_jointed.size()) m_jointed[c.m_solverBodyIdA] = 1;
		if (c.m_solverBodyIdB >= 0 && c.m_solverBodyIdB < m_jointed.size()) m_jointed[c.m_solverBodyIdB] = 1;
	}
	markDriven(pools);
	m_transferRows.resize(0);
	m_rowsOfBodyBuilt = false;
	m_composites.resize(0);
	m_compositeMembers.resize(0);
	m_active.resize(0);
	m_slipsAtSetup.resize(0);
	m_compositeOf.resize(numSolverBodies);
	m_inComposite.resize(numSolverBodies);
	m_carried.resize(numSolverBodies);
	for (int i = 0; i < numSolverBodies; ++i)
	{
		m_compositeOf[i] = -1;
		m_inComposite[i] = 0;
		m_carried[i] = 0;
	}
	m_withheld.reset(solverBodyOfNode.size(), pools.m_contacts.size());
	m_pushSpeed.resize(solverBodyOfNode.size());
	for (int i = 0; i < m_pushSpeed.size(); ++i) m_pushSpeed[i] = 0;
}

void btLayeredPasses::bucketFollowers(const btConstraintArray& rows, const btAlignedObjectArray<int>& contactLayer, btAlignedObjectArray<int>& start,
									 btAlignedObjectArray<int>& sorted)
{
	btAlignedObjectArray<int>& followLayer = m_scratchFollow;
	const int numRows = rows.size();
	followLayer.resize(numRows);
	for (int i = 0; i < numRows; ++i)
	{
		const int contact = rows[i].m_frictionIndex;
		followLayer[i] = (contact >= 0 && contact < contactLayer.size()) ? contactLayer[contact] : 0;
	}
	bucket(m_numLayers, numRows, numRows ? &followLayer[0] : 0, start, sorted, m_scratchCursor);
}

void btLayeredPasses::markFixated(int layer, char value)
{
	for (int i = 0; i < m_layers->getNumFixatedBodies(layer); ++i)
	{
		const int id = m_solverBodyOfNode[m_layers->getFixatedBody(layer, i)];
		if (id >= 0) m_fixated[id] = value;
	}
}

void btLayeredPasses::withholdFromFixated(const btSolverConstraint& row, bool sideA, btScalar impulse)
{
	// J_F^T impulse on the fixated end F, kept for it instead of applied.
	const int node = m_nodeOfSolverBody[sideA ? row.m_solverBodyIdA : row.m_solverBodyIdB];
	if (node < 0) return;
	m_withheld.add(node, (sideA ? row.m_contactNormal1 : row.m_contactNormal2) * impulse,
				   (sideA ? row.m_relpos1CrossNormal : row.m_relpos2CrossNormal) * impulse);
}

template <class Visit>
void btLayeredPasses::visitLayerRows(int layer, const btSolverPools& pools, Visit visit)
{
	if (hasJoints(layer, pools))
		for (int i = 0; i < pools.m_joints.size(); ++i) visit(pools.m_joints[i], BT_ROW_JOINT);
	for (int i = m_contactStart[layer]; i < m_contactStart[layer + 1]; ++i) visit(pools.m_contacts[m_contactRows[i]], BT_ROW_CONTACT);
	for (int i = m_frictionStart[layer]; i < m_frictionStart[layer + 1]; ++i) visit(pools.m_frictions[m_frictionRows[i]], BT_ROW_FRICTION);
	for (int i = m_rollingStart[layer]; i < m_rollingStart[layer + 1]; ++i)
		visit(pools.m_rollingFrictions[m_rollingRows[i]], BT_ROW_ROLLING_FRICTION);
}

template <class Visit>
void btLayeredPasses::visitBodyRows(int id, int layer, const btSolverPools& pools, Visit visit)
{
	if (layer < 0 || layer >= m_numLayers) return;
	if (!m_rowsOfBodyBuilt) buildRowsOfBody(pools);
	const int begin = m_contactStart[layer], end = m_contactStart[layer + 1];
	for (int p = m_rowsOfBodyStart[id]; p < m_rowsOfBodyStart[id + 1]; ++p)
	{
		const int r = m_rowsOfBody[p];
		if (r < begin) continue;
		if (r >= end) break;
		visit(static_cast<const btSolverConstraint&>(pools.m_contacts[m_contactRows[r]]), r);
	}
}

void btLayeredPasses::fixate(int layer, const btLayerFixationParams& params, const btSolverPools& pools)
{
	// Lower bodies of the layer (height <= layer): infinite mass while the layer is swept.
	markFixated(layer, 1);
	m_backups.resize(0);
	m_impulseBefore.resize(0);
	visitLayerRows(layer, pools, [&](btSolverConstraint& row, btSolverRowKind kind) {
		m_impulseBefore.push_back(row.m_appliedImpulse);
		const bool fixA = m_fixated[row.m_solverBodyIdA] != 0;
		const bool fixB = m_fixated[row.m_solverBodyIdB] != 0;
		// D23: a sliding base's friction rows see the mass of its composite.
		const int compA = compositeRowEnd(row.m_solverBodyIdA, kind);
		const int compB = compositeRowEnd(row.m_solverBodyIdB, kind);
		if (!fixA && !fixB && compA < 0 && compB < 0) return;
		m_backups.push_back(btBackupRow(row));
		// The contact normal of the row's contact (friction rows find it through m_frictionIndex).
		btVector3 normal(0, 0, 0);
		if (kind == BT_ROW_CONTACT) normal = row.m_contactNormal1.isZero() ? row.m_contactNormal2 : row.m_contactNormal1;
		else if (kind != BT_ROW_JOINT && row.m_frictionIndex >= 0 && row.m_frictionIndex < pools.m_contacts.size())
		{
			const btSolverConstraint& contact = pools.m_contacts[row.m_frictionIndex];
			normal = contact.m_contactNormal1.isZero() ? contact.m_contactNormal2 : contact.m_contactNormal1;
		}
		btFixateSolverRow(row, kind, pools.m_bodies[row.m_solverBodyIdA], pools.m_bodies[row.m_solverBodyIdB], fixA, fixB, params, normal,
						  driven(row.m_solverBodyIdA), driven(row.m_solverBodyIdB));
		if (compA >= 0 || compB >= 0)
			btCompositeFrictionRow(row, pools.m_bodies[row.m_solverBodyIdA], pools.m_bodies[row.m_solverBodyIdB],
								   compA >= 0 ? m_composites[compA].m_massRatio : btScalar(1), compB >= 0 ? m_composites[compB].m_massRatio : btScalar(1),
								   params.m_sor);
	});
	zeroFixatedMasses(layer, pools);
}

void btLayeredPasses::zeroFixatedMasses(int layer, const btSolverPools& pools)
{
	m_savedInvMass.resize(0);
	for (int i = 0; i < m_layers->getNumFixatedBodies(layer); ++i)
	{
		const int id = m_solverBodyOfNode[m_layers->getFixatedBody(layer, i)];
		if (id < 0) continue;
		btSolverBody& body = pools.m_bodies[id];
		m_savedInvMass.push_back(body.internalGetInvMass());
		body.internalSetInvMass(btVector3(0, 0, 0));
	}
}

void btLayeredPasses::restoreFixatedMasses(int layer, const btSolverPools& pools)
{
	int saved = 0;
	for (int i = 0; i < m_layers->getNumFixatedBodies(layer); ++i)
	{
		const int id = m_solverBodyOfNode[m_layers->getFixatedBody(layer, i)];
		if (id < 0) continue;
		pools.m_bodies[id].internalSetInvMass(m_savedInvMass[saved++]);
	}
}

void btLayeredPasses::handOnChange(const btSolverConstraint& c, btSolverRowKind kind, bool fixA, btScalar change, bool withhold,
								   const btSolverPools& pools)
{
	if (kind == BT_ROW_CONTACT) m_withheld.holdBack(int(&c - &pools.m_contacts[0]), change);
	if (!withhold || change == btScalar(0)) return;
	// The reaction this layer's impulse change owes the fixated end (J_F^T delta lambda).
	withholdFromFixated(c, fixA, change);
	if (kind == BT_ROW_CONTACT && c.m_jacDiagABInv != btScalar(0))
	{
		// How fast the free end pressed on the fixated one at setup (m/s along the normal):
		// a load handed down cannot push a body faster than that (D16 guard).
		const int node = m_nodeOfSolverBody[fixA ? c.m_solverBodyIdA : c.m_solverBodyIdB];
		if (node >= 0) m_pushSpeed[node] = btMax(m_pushSpeed[node], c.m_rhs / c.m_jacDiagABInv);
	}
}

void btLayeredPasses::release(int layer, bool withhold, const btSolverPools& pools)
{
	restoreFixatedMasses(layer, pools);
	int row = 0, backup = 0;
	visitLayerRows(layer, pools, [&](btSolverConstraint& c, btSolverRowKind kind) {
		const btScalar change = btScalar(c.m_appliedImpulse) - m_impulseBefore[row++];
		const bool fixA = m_fixated[c.m_solverBodyIdA] != 0;
		const bool fixB = m_fixated[c.m_solverBodyIdB] != 0;
		const bool composite = compositeRowEnd(c.m_solverBodyIdA, kind) >= 0 || compositeRowEnd(c.m_solverBodyIdB, kind) >= 0;
		if (!fixA && !fixB && !composite) return;
		btRestoreRow(c, m_backups[backup++]);
		if (!fixA && !fixB) return;
		handOnChange(c, kind, fixA, change, withhold, pools);
	});
	markFixated(layer, 0);
}

btScalar btLayeredPasses::sweep(int layer, int iteration, int sweeps, const btSolverPools& pools)
{
	btScalar worst = 0;
	// The order of a stock sweep (btSequentialImpulseConstraintSolver::solveSingleIteration,
	// contacts and friction not interleaved): joints, contact normals, friction bounded by the
	// normal impulse, rolling friction bounded by the normal impulse and its own coefficient.
	btAlignedObjectArray<btSolverBody>& bodies = pools.m_bodies;
	for (int i = 0; i < pools.m_joints.size() && hasJoints(layer, pools); ++i)
	{
		btSolverConstraint& c = pools.m_joints[i];
		if (iteration < c.m_overrideNumSolverIterations) noteResidual(worst, pools.m_generic(bodies[c.m_solverBodyIdA], bodies[c.m_solverBodyIdB], c));
	}
	if (iteration >= sweeps) return worst;  // extra sweeps for joints that ask for more only
	for (int i = m_contactStart[layer]; i < m_contactStart[layer + 1]; ++i)
	{
		btSolverConstraint& c = pools.m_contacts[m_contactRows[i]];
		noteResidual(worst, pools.m_lowerLimit(bodies[c.m_solverBodyIdA], bodies[c.m_solverBodyIdB], c));
	}
	// D23: while the friction rows are swept, a sliding base moves with its composite's mass.
	for (int i = 0; i < m_active.size(); ++i)
	{
		const btSlidingComposite& comp = m_composites[m_active[i]];
		bodies[comp.m_base].internalSetInvMass(comp.m_savedInvMass / comp.m_massRatio);
	}
	for (int i = m_frictionStart[layer]; i < m_frictionStart[layer + 1]; ++i)
	{
		btSolverConstraint& c = pools.m_frictions[m_frictionRows[i]];
		const btScalar normal = pools.m_contacts[c.m_frictionIndex].m_appliedImpulse;
		if (normal > btScalar(0))
		{
			c.m_lowerLimit = -(c.m_friction * normal);
			c.m_upperLimit = c.m_friction * normal;
			noteResidual(worst, pools.m_generic(bodies[c.m_solverBodyIdA], bodies[c.m_solverBodyIdB], c));
		}
	}
	for (int i = 0; i < m_active.size(); ++i)
	{
		const btSlidingComposite& comp = m_composites[m_active[i]];
		bodies[comp.m_base].internalSetInvMass(comp.m_savedInvMass);
	}
	for (int i = m_rollingStart[layer]; i < m_rollingStart[layer + 1]; ++i)
	{
		btSolverConstraint& c = pools.m_rollingFrictions[m_rollingRows[i]];
		const btScalar normal = pools.m_contacts[c.m_frictionIndex].m_appliedImpulse;
		if (normal > btScalar(0))
		{
			const btScalar magnitude = btMin(c.m_friction * normal, c.m_friction);
			c.m_lowerLimit = -magnitude;
			c.m_upperLimit = magnitude;
			noteResidual(worst, pools.m_generic(bodies[c.m_solverBodyIdA], bodies[c.m_solverBodyIdB], c));
		}
	}
	return worst;
}

int btLayeredPasses::solveLayer(int layer, const btLayerSweeps& sweeps, const btLayerFixationParams& params, bool withhold, const btSolverPools& pools)
{
	if (layer < 0 || layer >= m_numLayers) return 0;
	if (withhold && sweeps.m_compositeSlip > btScalar(0) && m_slipsAtSetup.size()) formComposites(layer, pools, sweeps.m_compositeSlip);
	fixate(layer, params, pools);
	// D19: each free body's block of rows against its fixated supports, solved in one step.
	if (sweeps.m_block) solveSupportRows(layer, pools, BT_SUPPORT_BLOCK);
	const bool joints = hasJoints(layer, pools);
	const int contactSweeps = joints ? sweeps.m_jointLayerMax : sweeps.m_max;
	const int total = joints ? btMax(contactSweeps, m_jointSweeps) : contactSweeps;
	// Then the sweeps: at least m_min, until one changes no row's velocity by more than the
	// convergence speed (D19), at most m_max (joints that ask for more get them).
	const btScalar converged2 = sweeps.m_convergedSpeed * sweeps.m_convergedSpeed;
	int run = 0;
	for (int iteration = 0; iteration < total; ++iteration)
	{
		const btScalar change = sweep(layer, iteration, contactSweeps, pools);
		++run;
		if (sweeps.m_min >= 0 && !joints && iteration + 1 >= sweeps.m_min && change <= converged2) break;
	}
	// D29: which free bodies slide on their supports as the layer ends (their friction at its bound).
	if (withhold && sweeps.m_markSliding && layer < m_layers->getNumLayers())
	{
		const int numFree = m_layers->getNumFreeBodies(layer);
		for (int i = 0; i < numFree; ++i)
		{
			const int id = m_solverBodyOfNode[m_layers->getFreeBody(layer, i)];
			if (id >= 0) m_slidUp[id] = slidesOnSupport(layer, i, pools) ? 1 : 0;
		}
	}
	release(layer, withhold, pools);
	if (m_active.size()) carryComposites(layer, pools);
	return run;
}

void btLayeredPasses::withholdUnfeltWarmStart(const btSolverPools& pools, btScalar warmstartingFactor, btScalar coupling)
{
	// Bullet's setup applied each contact row's warm start, factor x T, to both ends. Last step,
	// the lower end felt only F of T (the share stored in the point, btWithheldReactions): take
	// (1 - coupling) of the rest back from it and hold it back again, as the layer passes would.
	for (int layer = 0; layer < m_numLayers && layer < m_layers->getNumLayers(); ++layer)
	{
		markFixated(layer, 1);
		for (int i = m_contactStart[layer]; i < m_contactStart[layer + 1]; ++i)
		{
			const int rowIndex = m_contactRows[i];
			btSolverConstraint& c = pools.m_contacts[rowIndex];
			const btScalar warm = c.m_appliedImpulse;
			if (!(warm > btScalar(0))) continue;
			const bool fixA = m_fixated[c.m_solverBodyIdA] != 0;
			const bool fixB = m_fixated[c.m_solverBodyIdB] != 0;
			if (fixA == fixB) continue;
			const btScalar felt = btMin(warm, btMax(btScalar(0), warmstartingFactor * m_pointFelt[rowIndex]));
			const btScalar unfelt = (warm - felt) * (btScalar(1) - coupling);
			if (!(unfelt > btScalar(0))) continue;
			const int id = fixA ? c.m_solverBodyIdA : c.m_solverBodyIdB;
			btSolverBody& body = pools.m_bodies[id];
			if (fixA) body.internalApplyImpulse(c.m_contactNormal1 * body.internalGetInvMass(), c.m_angularComponentA, -unfelt);
			else body.internalApplyImpulse(c.m_contactNormal2 * body.internalGetInvMass(), c.m_angularComponentB, -unfelt);
			withholdFromFixated(c, fixA, unfelt);
			m_withheld.holdBack(rowIndex, unfelt);
		}
		markFixated(layer, 0);
	}
}

void btLayeredPasses::storeFeltShares(const btSolverPools& pools, bool delivered)
{
	for (int i = 0; i < pools.m_contacts.size(); ++i)
	{
		const btSolverConstraint& c = pools.m_contacts[i];
		btManifoldPoint* cp = static_cast<btManifoldPoint*>(c.m_originalContactPoint);
		const btScalar total = c.m_appliedImpulse;
		btWithheldReactions::setFeltShare(*cp, delivered ? total : btMax(btScalar(0), total - m_withheld.heldBack(i)));
	}
}

bool btLayeredPasses::receiveWithheld(int layer, const btSolverPools& pools)
{
	// The free bodies of the layer get the impulses the layers above withheld from them.
	bool any = false;
	const int numFree = layer < m_layers->getNumLayers() ? m_layers->getNumFreeBodies(layer) : 0;
	for (int i = 0; i < numFree; ++i)
	{
		const int node = m_layers->getFreeBody(layer, i);
		if (!m_withheld.has(node)) continue;
		const int id = m_solverBodyOfNode[node];
		if (id < 0)
		{
			m_withheld.discard(node);
			continue;
		}
		m_withheld.deliver(node, pools.m_bodies[id]);
		any = true;
	}
	return any;
}

int btLayeredPasses::solveWeightPass(int sweeps, const btLayerFixationParams& params, const btSolverPools& pools, const btWeightPassParams& weight,
									 int* rejected)
{
	// Joint rows (all in layer 0, D8) are not re-solved here: they are no part of the load handed
	// down, and their bodies may sit in layers already final (a rejection could not undo them).
	m_withJoints = false;
	int total = 0;
	// D25: the loads rejected layers give back, per solver body (zero where none; only the bodies a
	// rejection touched are cleared again below, so a settled step does no work here).
	if (weight.m_tippingComposites && m_discardedLinear.size() != pools.m_bodies.size())
	{
		m_discardedLinear.resize(pools.m_bodies.size());
		m_discardedAngular.resize(pools.m_bodies.size());
		for (int i = 0; i < pools.m_bodies.size(); ++i)
		{
			m_discardedLinear[i].setZero();
			m_discardedAngular[i].setZero();
		}
	}
	for (int k = m_numLayers - 1; k >= 0; --k)
	{
		// The layer's free bodies before their load arrives (to judge and, if need be, undo the re-solve).
		const int numFree = k < m_layers->getNumLayers() ? m_layers->getNumFreeBodies(k) : 0;
		m_before.resize(numFree);
		for (int i = 0; i < numFree; ++i)
		{
			const int id = m_solverBodyOfNode[m_layers->getFreeBody(k, i)];
			if (id < 0) continue;
			btSolverBody& b = pools.m_bodies[id];
			m_before[i].m_deltaLinear = b.internalGetDeltaLinearVelocity();
			m_before[i].m_deltaAngular = b.internalGetDeltaAngularVelocity();
		}
		if (!receiveWithheld(k, pools)) continue;  // nothing rests on this layer's bodies
		for (int i = 0; i < numFree; ++i)
		{
			const int id = m_solverBodyOfNode[m_layers->getFreeBody(k, i)];
			m_before[i].m_loadLinear = id < 0 ? btVector3(0, 0, 0) : pools.m_bodies[id].internalGetDeltaLinearVelocity() - m_before[i].m_deltaLinear;
			m_before[i].m_loadAngular = id < 0 ? btVector3(0, 0, 0) : pools.m_bodies[id].internalGetDeltaAngularVelocity() - m_before[i].m_deltaAngular;
		}
		// D23: the layer's sliding bases move with their composites again.
		if (weight.m_compositeTolerance > btScalar(0) && m_composites.size()) activateComposites(k, pools, weight.m_compositeTolerance);
		const bool withComposites = m_active.size() > 0;
		// D20: loads a re-solve would call converged before its first sweep are taken by the
		// support rows alone (load transfer) and the changes handed on.
		if (!withComposites && weight.m_transfer && weight.m_transferSmallLoads && loadsBelow(k, pools, weight.m_convergedSpeed))
		{
			transferOnly(k, pools);
			continue;
		}
		fixate(k, params, pools);
		if (weight.m_transfer) solveSupportRows(k, pools, BT_SUPPORT_LOAD_TRANSFER);
		// Sweeps until the re-solve converges (no row's velocity changed by more than
		// m_convergedSpeed in the last sweep), at most `sweeps`.
		const btScalar converged2 = weight.m_convergedSpeed * weight.m_convergedSpeed;
		btScalar lastChange = 0;
		for (int iteration = 0; iteration < sweeps; ++iteration)
		{
			lastChange = sweep(k, iteration, sweeps, pools);
			++total;
			if (lastChange <= converged2) break;
		}
		// D31: the sweeps' last error, a spurious turn of each body, removed by its support block.
		if (weight.m_finalBlocks) solveSupportRows(k, pools, BT_SUPPORT_BLOCK);
		// D16 guard. A load handed down cannot push a body faster than the bodies that pressed it
		// on it moved towards it (an inelastic push), plus the slack. A re-solve that leaves a
		// free body's centre of mass faster than that could not carry its load within its sweeps,
		// unless it converged, the gain stays within m_tipGain steps of free fall, and the body
		// either slides (D17: dragged along its supports by the load's tangential part, no more)
		// or tips where statics says it must (its weight and load act outside its support, and it
		// pivots rather than sinks).
		const bool converged = lastChange <= converged2;
		if (withComposites) shareCompositeMotion(k, pools);
		bool anyRejected = false;
		m_tipFirst.resize(0);
		m_tipBase.resize(0);
		m_tipSlides.resize(0);
		m_tipMembers.resize(0);
		// D26: a rejection restores the free bodies of the layer in the rejected body's island (its
		// component of the contact graph) instead of every free body of the layer.
		const bool perIsland = weight.m_rejectPerIsland && !withComposites;
		m_rejectLocal.resize(numFree);
		for (int i = 0; i < numFree; ++i) m_rejectLocal[i] = 0;
		for (int i = 0; i < numFree; ++i)
		{
			const int node = m_layers->getFreeBody(k, i);
			const int id = m_solverBodyOfNode[node];
			if (id < 0) continue;
			btSolverBody& b = pools.m_bodies[id];
			const btVector3 g = b.m_originalBody ? b.m_originalBody->getGravity() : btVector3(0, 0, 0);
			const btScalar fall = g.length() * weight.m_timeStep;
			const btVector3 base = b.m_linearVelocity + b.m_externalForceImpulse;
			const btScalar after = (base + b.internalGetDeltaLinearVelocity()).length();
			const btScalar before = (base + m_before[i].m_deltaLinear).length();
			btScalar pointAfter = after, pointBefore = before;
			if (weight.m_guardSpin && !converged && b.m_originalBody && b.m_originalBody->getInvMass() > btScalar(0))
			{
				// D28: an unconverged re-solve is judged by the speed of the body's kinetic energy,
				// sqrt(2 E / m) = sqrt(v^2 + w . I w / m): its spin is no solution either (a converged
				// one's is its layer's answer, and a body that tips turns).
				const btRigidBody* rb = b.m_originalBody;
				const btMatrix3x3& invInertia = rb->getInvInertiaTensorWorld();
				const btVector3 spin = b.m_angularVelocity + b.m_externalTorqueImpulse;
				const auto energySpeed = [&](btScalar linear, const btVector3& w) {
					const btVector3 L = invInertia.solve33(w);  // I w
					return btSqrt(linear * linear + btMax(btScalar(0), w.dot(L)) * rb->getInvMass());
				};
				pointAfter = energySpeed(after, spin + b.internalGetDeltaAngularVelocity());
				pointBefore = energySpeed(before, spin + m_before[i].m_deltaAngular);
			}
			// D29: a body that slides on its supports after its layer pass and after its re-solve
			// carries what rests on it as one rigid body, whatever the guard would say (a re-solve
			// the guard accepts still leaves the bodies above at the velocity the layer pass dragged
			// them to). Kept only if every member can stick to what carries it.
			if (weight.m_rigidSliding && fall > btScalar(0) && !withComposites && m_slidUp[id] &&
				slidesOnSupport(k, i, pools) && tipWithMembers(k, i, sweeps, weight, pools, &total, false, true))
				continue;
			if (pointAfter <= pointBefore + m_pushSpeed[node] + weight.m_slack * fall) continue;
			// D25: where statics says the body must tip, it tips with what rests on it, as one
			// rigid body (tipWithMembers: kept only if the composite's statics says so too, its
			// solve adds no energy and no member speeds up beyond m_tipGain steps of free fall;
			// else the clauses below judge the body alone).
			// D27: a load beyond m_tipGain steps of free fall is an impact (something landed).
			const bool impact = weight.m_impactTipping && m_before[i].m_loadLinear.length() > weight.m_tipGain * fall;
			if (weight.m_tippingComposites && fall > btScalar(0) && !withComposites &&
				loadOutsideSupport(k, node, pools, weight.m_timeStep, weight.m_tipMargin) && tipWithMembers(k, i, sweeps, weight, pools, &total, impact))
				continue;
			if (converged && after <= before + weight.m_tipGain * fall && fall > btScalar(0))
			{
				const btVector3 dv = b.internalGetDeltaLinearVelocity() - m_before[i].m_deltaLinear;
				const btScalar slack = weight.m_slack * fall;
				// Sliding: friction only resists, so along the supports' tangent plane a load cannot
				// speed a body up by more than the load alone would (on a frictionless support), and
				// a sliding body neither sinks into its supports nor lifts off them.
				const btVector3 n = supportNormal(k, id, g, pools);
				const btVector3& load = m_before[i].m_loadLinear;
				const btScalar dvn = dv.dot(n);
				if (btFabs(dvn) <= slack && (dv - n * dvn).length() <= (load - n * load.dot(n)).length() + slack) continue;
				// Tipping pivots a body on its support; a body pressed down into what is below it
				// has not carried its load. (The rows the statics test reads are not changed by
				// the re-solve: the load rests on the layer above, the support points are geometry.)
				const btScalar sink = dv.dot(g) / g.length();
				if (sink <= slack && loadOutsideSupport(k, node, pools, weight.m_timeStep, weight.m_tipMargin)) continue;
			}
			anyRejected = true;
			m_rejectLocal[i] = 1;
			if (!perIsland) break;
		}
		if (anyRejected) rejectIslands(k, perIsland);
		// D25: the members of the layer's tipping composites keep the rigid motion if the layer
		// stands (their rejected loads are now in it), else they get their velocities back (the
		// layer's own free bodies, the bases, then their state from before the load).
		for (int t = 0; t < m_tipFirst.size(); ++t)
		{
			const int end = t + 1 < m_tipFirst.size() ? m_tipFirst[t + 1] : m_tipMembers.size();
			const bool undone = anyRejected && m_rejectLocal[m_tipBase[t]];
			if (undone)
			{
				restoreTipMembers(m_tipFirst[t], end, pools);
				continue;
			}
			for (int j = m_tipFirst[t]; j < end; ++j)
			{
				m_discardedLinear[m_tipMembers[j]].setZero();
				m_discardedAngular[m_tipMembers[j]].setZero();
			}
			++m_tippingComposites;
			if (m_tipSlides[t]) ++m_rigidSlidingComposites;
		}
		if (anyRejected)
		{
			// The rejected islands keep their state from before their load (free bodies and rows).
			indexFreeBodies(k, pools);
			int row = 0;
			visitLayerRows(k, pools, [&](btSolverConstraint& c, btSolverRowKind) {
				const btScalar before = m_impulseBefore[row++];
				const int a = m_localOf[c.m_solverBodyIdA], b = m_localOf[c.m_solverBodyIdB];
				if ((a >= 0 && m_rejectLocal[a]) || (b >= 0 && m_rejectLocal[b])) c.m_appliedImpulse = before;
			});
			unindexFreeBodies(k);
			for (int i = 0; i < numFree; ++i)
			{
				const int id = m_solverBodyOfNode[m_layers->getFreeBody(k, i)];
				if (id < 0 || !m_rejectLocal[i]) continue;
				pools.m_bodies[id].internalGetDeltaLinearVelocity() = m_before[i].m_deltaLinear;
				pools.m_bodies[id].internalGetDeltaAngularVelocity() = m_before[i].m_deltaAngular;
				if (weight.m_tippingComposites)
				{
					m_discardedLinear[id] += m_before[i].m_loadLinear;
					m_discardedAngular[id] += m_before[i].m_loadAngular;
					m_discardedIds.push_back(id);
				}
			}
			if (rejected) ++*rejected;
		}
		for (int t = 0; t < m_tipMembers.size(); ++t) m_tipOf[m_tipMembers[t]] = 0;
		release(k, true, pools);  // a rejected layer's rows changed nothing: nothing is withheld
		if (withComposites) deactivateComposites(!anyRejected, pools);
	}
	for (int i = 0; i < m_discardedIds.size(); ++i)
	{
		m_discardedLinear[m_discardedIds[i]].setZero();
		m_discardedAngular[m_discardedIds[i]].setZero();
	}
	m_discardedIds.resize(0);
	m_withJoints = true;
	return total;
}

bool btLayeredPasses::slidesOnSupport(int layer, int local, const btSolverPools& pools)
{
	gatherSupportRows(layer, pools);
	const int slot = m_freeSlot[layer] + local;
	for (int r = m_supportBegin[slot]; r < m_supportEnd[slot]; ++r)
	{
		const btLoadTransferRow& row = m_transferRows[r];
		if (row.m_contact) continue;
		const btScalar bound = btFrictionBound(*row.m_row, pools.m_contacts);
		if (bound > btScalar(0) && btFabs(row.m_row->m_appliedImpulse) >= btScalar(0.99) * bound) return true;
	}
	return false;
}

bool btLayeredPasses::membersStick(int first, int mark, btScalar slack, const btSolverPools& pools)
{
	// Per member above the base: its height, its mass, the impulse it took this step (m dv: from
	// last step's velocity and this step's forces to the composite's motion) and its contacts on
	// members below it (normals into the member, summed; the smallest friction coefficient).
	const int n = m_tipMembers.size() - first - 1;
	m_stickLevels.resize(n);
	for (int j = 0; j < n; ++j)
	{
		const int member = m_tipMembers[first + 1 + j];
		btSolverBody& b = pools.m_bodies[member];
		btStickLevel& level = m_stickLevels[j];
		level.m_height = m_layers->getHeight(m_nodeOfSolverBody[member]);
		level.m_mass = btScalar(1) / b.m_originalBody->getInvMass();
		level.m_impulse = b.internalGetDeltaLinearVelocity() * level.m_mass;
		level.m_normal.setZero();
		level.m_mu = BT_LARGE_FLOAT;
		visitBodyRows(member, level.m_height - 1, pools, [&](const btSolverConstraint& row, int) {
			const int other = row.m_solverBodyIdA == member ? row.m_solverBodyIdB : row.m_solverBodyIdA;
			if (m_tipOf[other] != mark) return;
			level.m_normal += row.m_solverBodyIdA == member ? row.m_contactNormal1 : row.m_contactNormal2;
			level.m_mu = btMin(level.m_mu, btScalar(row.m_friction));
		});
	}
	// Each height is a cut through the composite: the contacts under the members at that height
	// carry the impulses of every member at or above it (for a column, exactly; a composite that
	// turns gives its higher members more than its lower ones, so a member's own change is not
	// what its contacts carry). The cut sticks if that sum, per unit of the mass above, has a part
	// across the cut's mean normal within the smallest mu times the part along it, plus `slack`.
	for (int j = 0; j < n; ++j)
	{
		const int height = m_stickLevels[j].m_height;
		bool done = false;
		for (int i = 0; i < j && !done; ++i) done = m_stickLevels[i].m_height == height;
		if (done) continue;
		btVector3 impulse(0, 0, 0), normal(0, 0, 0);
		btScalar mass = 0, mu = BT_LARGE_FLOAT;
		for (int i = 0; i < n; ++i)
		{
			const btStickLevel& level = m_stickLevels[i];
			if (level.m_height < height) continue;
			impulse += level.m_impulse;
			mass += level.m_mass;
			if (level.m_height == height && level.m_normal.length2() > SIMD_EPSILON)
			{
				normal += level.m_normal;
				mu = btMin(mu, level.m_mu);
			}
		}
		if (!(normal.length2() > SIMD_EPSILON)) continue;  // nothing at this height rests on a member directly
		normal.normalize();
		const btVector3 change = impulse / mass;
		const btScalar along = change.dot(normal);
		const btScalar across = (change - normal * along).length();
		if (!(across <= mu * btMax(btScalar(0), along) + slack)) return false;
	}
	return true;
}

bool btLayeredPasses::loadsBelow(int layer, const btSolverPools& pools, btScalar speed)
{
	// Every free body's velocity change from its load, at its farthest point (linear plus angular
	// times the bounding radius of its shape), and what that momentum would do to each body it
	// rests on: a heavy body's small change is a large one for a light support.
	const int numFree = m_layers->getNumFreeBodies(layer);
	indexFreeBodies(layer, pools);
	m_loadSpeed.resize(numFree);
	bool small = true;
	for (int i = 0; i < numFree && small; ++i)
	{
		m_loadSpeed[i] = 0;
		const int id = m_solverBodyOfNode[m_layers->getFreeBody(layer, i)];
		if (id < 0) continue;
		btSolverBody& b = pools.m_bodies[id];
		btScalar radius = 0;
		if (b.m_originalBody)
		{
			btVector3 centre;
			b.m_originalBody->getCollisionShape()->getBoundingSphere(centre, radius);
		}
		const btVector3 dw = b.internalGetDeltaAngularVelocity() - m_before[i].m_deltaAngular;
		m_loadSpeed[i] = m_before[i].m_loadLinear.length() + dw.length() * radius;
		if (!(m_loadSpeed[i] <= speed)) small = false;
	}
	if (small)
	{
		markFixated(layer, 1);
		for (int r = m_contactStart[layer]; r < m_contactStart[layer + 1] && small; ++r)
		{
			const btSolverConstraint& c = pools.m_contacts[m_contactRows[r]];
			const bool fixA = m_fixated[c.m_solverBodyIdA] != 0;
			const bool fixB = m_fixated[c.m_solverBodyIdB] != 0;
			if (fixA == fixB) continue;
			const btSolverBody& fixed = pools.m_bodies[fixA ? c.m_solverBodyIdA : c.m_solverBodyIdB];
			const btSolverBody& free = pools.m_bodies[fixA ? c.m_solverBodyIdB : c.m_solverBodyIdA];
			const int local = m_localOf[fixA ? c.m_solverBodyIdB : c.m_solverBodyIdA];
			if (local < 0 || !fixed.m_originalBody || !free.m_originalBody) continue;
			const btScalar ratio = fixed.m_originalBody->getInvMass() / free.m_originalBody->getInvMass();
			if (!(m_loadSpeed[local] * ratio <= speed)) small = false;
		}
		markFixated(layer, 0);
	}
	unindexFreeBodies(layer);
	return small;
}

void btLayeredPasses::indexFreeBodies(int layer, const btSolverPools& pools)
{
	const int numSolverBodies = pools.m_bodies.size();
	if (m_localOf.size() != numSolverBodies)
	{
		m_localOf.resize(numSolverBodies);
		for (int i = 0; i < numSolverBodies; ++i) m_localOf[i] = -1;
	}
	for (int i = 0; i < m_layers->getNumFreeBodies(layer); ++i)
	{
		const int id = m_solverBodyOfNode[m_layers->getFreeBody(layer, i)];
		if (id >= 0) m_localOf[id] = i;
	}
}

void btLayeredPasses::unindexFreeBodies(int layer)
{
	for (int i = 0; i < m_layers->getNumFreeBodies(layer); ++i)
	{
		const int id = m_solverBodyOfNode[m_layers->getFreeBody(layer, i)];
		if (id >= 0) m_localOf[id] = -1;
	}
}

void btLayeredPasses::transferOnly(int layer, const btSolverPools& pools)
{
	// The lower bodies immovable (inverse mass zero, rows untouched: the load transfer reads only
	// the free end of each row), the support rows take the loads, and each row's change is
	// withheld for the layer below as a re-solve's would be (release()).
	markFixated(layer, 1);
	m_impulseBefore.resize(0);
	visitLayerRows(layer, pools, [&](btSolverConstraint& c, btSolverRowKind) { m_impulseBefore.push_back(c.m_appliedImpulse); });
	zeroFixatedMasses(layer, pools);
	solveSupportRows(layer, pools, BT_SUPPORT_LOAD_TRANSFER);
	restoreFixatedMasses(layer, pools);
	int row = 0;
	visitLayerRows(layer, pools, [&](btSolverConstraint& c, btSolverRowKind kind) {
		const btScalar change = btScalar(c.m_appliedImpulse) - m_impulseBefore[row++];
		const bool fixA = m_fixated[c.m_solverBodyIdA] != 0;
		const bool fixB = m_fixated[c.m_solverBodyIdB] != 0;
		if (fixA == fixB) return;
		handOnChange(c, kind, fixA, change, true, pools);
	});
	markFixated(layer, 0);
}

void btLayeredPasses::gatherSupportRows(int layer, const btSolverPools& pools)
{
	if (m_supportGathered[layer]) return;
	m_supportGathered[layer] = 1;
	const int numFree = layer < m_layers->getNumLayers() ? m_layers->getNumFreeBodies(layer) : 0;
	if (numFree == 0) return;
	indexFreeBodies(layer, pools);
	// Rows with one end free in this layer and the other fixated, grouped by the free body.
	auto freeEnd = [&](const btSolverConstraint& c, bool& sideA) -> int {
		// Fixated here, or static (Bullet's shared fixed body): no inverse mass while the layer is solved.
		const bool fixA = pools.m_bodies[c.m_solverBodyIdA].internalGetInvMass().isZero();
		const bool fixB = pools.m_bodies[c.m_solverBodyIdB].internalGetInvMass().isZero();
		if (fixA == fixB) return -1;
		sideA = !fixA;
		return m_localOf[sideA ? c.m_solverBodyIdA : c.m_solverBodyIdB];
	};
	m_transferStart.resize(numFree + 1);
	for (int i = 0; i <= numFree; ++i) m_transferStart[i] = 0;
	auto countRows = [&](const btConstraintArray& pool, const btAlignedObjectArray<int>& start, const btAlignedObjectArray<int>& sorted) {
		for (int i = start[layer]; i < start[layer + 1]; ++i)
		{
			bool sideA;
			const int local = freeEnd(pool[sorted[i]], sideA);
			if (local >= 0) ++m_transferStart[local + 1];
		}
	};
	countRows(pools.m_contacts, m_contactStart, m_contactRows);
	countRows(pools.m_frictions, m_frictionStart, m_frictionRows);
	for (int i = 0; i < numFree; ++i) m_transferStart[i + 1] += m_transferStart[i];
	const int base = m_transferRows.size();
	m_transferRows.resize(base + m_transferStart[numFree]);
	m_transferCursor.resize(numFree);
	for (int i = 0; i < numFree; ++i)
	{
		m_transferCursor[i] = base + m_transferStart[i];
		m_supportBegin[m_freeSlot[layer] + i] = base + m_transferStart[i];
		m_supportEnd[m_freeSlot[layer] + i] = base + m_transferStart[i + 1];
	}
	auto fillRows = [&](btConstraintArray& pool, const btAlignedObjectArray<int>& start, const btAlignedObjectArray<int>& sorted, bool contact) {
		for (int i = start[layer]; i < start[layer + 1]; ++i)
		{
			bool sideA;
			btSolverConstraint& c = pool[sorted[i]];
			const int local = freeEnd(c, sideA);
			if (local < 0) continue;
			const int point = contact ? sorted[i] : c.m_frictionIndex;
			const bool carried = point >= 0 && point < m_pointCarried.size() && m_pointCarried[point];
			m_transferRows[m_transferCursor[local]++] = btLoadTransferRow{&c, sideA, contact, i - start[layer], carried};
		}
	};
	fillRows(pools.m_contacts, m_contactStart, m_contactRows, true);
	fillRows(pools.m_frictions, m_frictionStart, m_frictionRows, false);
	unindexFreeBodies(layer);
}

void btLayeredPasses::solveSupportRows(int layer, const btSolverPools& pools, btSupportSolve solve)
{
	const int numFree = layer < m_layers->getNumLayers() ? m_layers->getNumFreeBodies(layer) : 0;
	if (numFree == 0) return;
	gatherSupportRows(layer, pools);
	for (int i = 0; i < numFree; ++i)
	{
		const int id = m_solverBodyOfNode[m_layers->getFreeBody(layer, i)];
		if (id < 0) continue;
		btSolverBody& b = pools.m_bodies[id];
		const int slot = m_freeSlot[layer] + i;
		const int first = m_supportBegin[slot];
		const int n = m_supportEnd[slot] - first;
		if (n > 0 && solve == BT_SUPPORT_BLOCK && compositeOf(id) >= 0) continue;  // D23: its friction is the composite's
		// D24: the block keeps its factor for the weight pass's transfer of the same body and rows.
		if (n > 0 && solve == BT_SUPPORT_BLOCK)
			btSolveSupportBlock(b, pools.m_bodies, &m_transferRows[first], n, pools.m_contacts, m_shareFactor ? &m_blockFactor[slot] : 0,
								m_shareFactor ? &m_blockFactorValid[slot] : 0);
		else if (n > 0 && m_shareFactor && m_blockFactorValid[slot])
		{
			btTransferLoad(b, m_before[i].m_deltaLinear, m_before[i].m_deltaAngular, &m_transferRows[first], n, pools.m_contacts, m_blockFactor[slot]);
			++m_sharedFactorTransfers;
		}
		else if (n > 0) btTransferLoad(b, m_before[i].m_deltaLinear, m_before[i].m_deltaAngular, &m_transferRows[first], n, pools.m_contacts);
	}
}


bool btLayeredPasses::loadOutsideSupport(int layer, int node, const btSolverPools& pools, btScalar timeStep, btScalar margin)
{
	// The body's weight and the load of the contacts resting on it (an impulse P with moment A
	// about the centre of mass c) act along a line; where it meets the plane of the body's support points, p, tells
	// statics' answer: inside the convex hull of the support points the supports can carry it,
	// outside the body must tip (the statics of a rigid body on unilateral contacts).
	const int id = m_solverBodyOfNode[node];
	if (id < 0) return false;
	const btSolverBody& body = pools.m_bodies[id];
	const btRigidBody* rb = body.m_originalBody;
	if (!rb || rb->getInvMass() == btScalar(0)) return false;
	const btVector3 g = rb->getGravity();
	const btScalar gLength = g.length();
	if (!(gLength > SIMD_EPSILON)) return false;
	const btVector3 up = -g / gLength;
	btVector3 P = g * (timeStep / rb->getInvMass());
	btVector3 A(0, 0, 0);
	// The whole load of the contacts resting on it (the layer above), normal parts only: the
	// friction PGS leaves between a body and its supports is not determined by statics (a
	// squeeze), and would tip what carries it.
	visitBodyRows(id, layer + 1, pools, [&](const btSolverConstraint& row, int) {
		const btScalar lambda = row.m_appliedImpulse;
		if (row.m_solverBodyIdA == id)
		{
			P += row.m_contactNormal1 * lambda;
			A += row.m_relpos1CrossNormal * lambda;
		}
		else
		{
			P += row.m_contactNormal2 * lambda;
			A += row.m_relpos2CrossNormal * lambda;
		}
	});
	const btScalar down = -P.dot(up);
	if (!(down > SIMD_EPSILON)) return false;  // nothing pressing down: no statics to judge
	return lineOutsideSupport(layer, id, P, P.cross(A) / P.length2(), margin, pools);
}

bool btLayeredPasses::lineOutsideSupport(int layer, int id, const btVector3& P, const btVector3& d0, btScalar margin, const btSolverPools& pools)
{
	const btRigidBody* rb = pools.m_bodies[id].m_originalBody;
	const btVector3 up = -rb->getGravity().normalized();
	// Support points: the contact points of the layer's rows with this body as the free end.
	const btVector3 c = rb->getCenterOfMassPosition();
	btVector3 u, v;
	btPlaneSpace1(up, u, v);
	m_hull.resize(0);
	btScalar plane = SIMD_INFINITY;
	visitBodyRows(id, layer, pools, [&](const btSolverConstraint& row, int) {
		const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
		if (!cp) return;
		const btVector3 n = row.m_solverBodyIdA == id ? row.m_contactNormal1 : row.m_contactNormal2;
		if (n.dot(up) < btScalar(0.5)) return;  // side contacts do not carry weight
		const btVector3 x = cp->getPositionWorldOnB() - c;
		plane = btMin(plane, x.dot(up));
		m_hull.push_back(btVector3(x.dot(u), x.dot(v), 0));
	});
	if (m_hull.size() == 0) return false;
	// The line of action: d x P = A, d = d0 + t P; at the support plane d . up = plane.
	const btScalar t = (plane - d0.dot(up)) / P.dot(up);
	const btVector3 d = d0 + P * t;
	const btScalar px = d.dot(u), py = d.dot(v);
	// Convex hull of the support points (monotone chain), then p against each edge.
	const int n = m_hull.size();
	m_hull.quickSort([](const btVector3& a, const btVector3& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
	auto cross = [](const btVector3& o, const btVector3& a, const btVector3& b) { return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x()); };
	m_hullChain.resize(0);
	for (int pass = 0; pass < 2; ++pass)
	{
		const int start = m_hullChain.size();
		for (int i = 0; i < n; ++i)
		{
			const btVector3& q = m_hull[pass == 0 ? i : n - 1 - i];
			while (m_hullChain.size() >= start + 2 && cross(m_hullChain[m_hullChain.size() - 2], m_hullChain[m_hullChain.size() - 1], q) <= btScalar(0))
				m_hullChain.pop_back();
			m_hullChain.push_back(q);
		}
		m_hullChain.pop_back();
	}
	if (m_hullChain.size() < 3) return true;  // resting on an edge or a point: any moment tips it
	// Outside by more than `margin` of the hull's size (a load near the edge is carried: the
	// split of a load between a manifold's points is not determined by statics).
	btScalar size = 0;
	for (int i = 0; i < m_hullChain.size(); ++i) size = btMax(size, (m_hullChain[i] - m_hullChain[0]).length());
	const btVector3 p(px, py, 0);
	for (int i = 0; i < m_hullChain.size(); ++i)
	{
		const btVector3& a = m_hullChain[i];
		const btVector3& b = m_hullChain[(i + 1) % m_hullChain.size()];
		const btScalar edge = (b - a).length();
		if (edge > SIMD_EPSILON && cross(a, b, p) / edge < -margin * size) return true;
	}
	return false;
}

btVector3 btLayeredPasses::supportNormal(int layer, int id, const btVector3& gravity, const btSolverPools& pools)
{
	// The mean normal of the body's supports in this layer (pointing into the body); without any,
	// against gravity.
	btVector3 n(0, 0, 0);
	visitBodyRows(id, layer, pools, [&](const btSolverConstraint& row, int) { n += row.m_solverBodyIdA == id ? row.m_contactNormal1 : row.m_contactNormal2; });
	if (!(n.length2() > SIMD_EPSILON)) n = -gravity;
	if (!(n.length2() > SIMD_EPSILON)) return btVector3(0, 0, 0);
	return n.normalized();
}

void btLayeredPasses::restorePairLoads(btPersistentManifold** manifolds, int numManifolds, btScalar restSpeed)
{
	for (int i = 0; i < numManifolds; ++i)
	{
		btPersistentManifold* m = manifolds[i];
		int fresh = 0;
		for (int j = 0; j < m->getNumContacts(); ++j) fresh += isNewPoint(m->getContactPoint(j)) ? 1 : 0;
		// A pair whose points are all new is a new contact (a landing, a bounce): its last load was
		// no resting load. Only points that replace or join persisting ones inherit. (Tested before
		// the look-up: most pairs have no new point.)
		if (fresh == 0 || fresh == m->getNumContacts()) continue;
		const btPairLoad* found = findPairLoad(m, m_pairLoadCursor + i);
		if (!found || found->m_body0 != m->getBody0() || found->m_body1 != m->getBody1()) continue;
		const btScalar missing = found->m_total - totalNormalImpulse(*m);
		if (!(missing > btScalar(0))) continue;
		// Only a resting pair keeps its load: every new point's relative velocity is below restSpeed
		// (a body that tips or slides off its support makes new points at a moving edge).
		const btRigidBody* a = btRigidBody::upcast(m->getBody0());
		const btRigidBody* b = btRigidBody::upcast(m->getBody1());
		bool resting = true;
		for (int j = 0; j < m->getNumContacts() && resting; ++j)
		{
			const btManifoldPoint& cp = m->getContactPoint(j);
			if (!isNewPoint(cp)) continue;
			const btVector3 va = a ? a->getVelocityInLocalPoint(cp.getPositionWorldOnA() - a->getCenterOfMassPosition()) : btVector3(0, 0, 0);
			const btVector3 vb = b ? b->getVelocityInLocalPoint(cp.getPositionWorldOnB() - b->getCenterOfMassPosition()) : btVector3(0, 0, 0);
			resting = (va - vb).length() < restSpeed;
		}
		if (!resting) continue;
		for (int j = 0; j < m->getNumContacts(); ++j)
		{
			btManifoldPoint& cp = m->getContactPoint(j);
			if (!isNewPoint(cp)) continue;
			cp.m_appliedImpulse = missing / btScalar(fresh);
			btWithheldReactions::setFeltShare(cp, cp.m_appliedImpulse);
		}
	}
	m_pairLoadCursor += numManifolds;
}

void btLayeredPasses::recordPairLoads(btPersistentManifold** manifolds, int numManifolds)
{
	for (int i = 0; i < numManifolds; ++i)
	{
		const btPersistentManifold* m = manifolds[i];
		m_pairLoadsThisStep.push_back(btPairLoad{m, m->getBody0(), m->getBody1(), totalNormalImpulse(*m)});
	}
}

void btLayeredPasses::endStep()
{
	m_pairLoadsLastStep.copyFromArray(m_pairLoadsThisStep);  // within the capacity: no allocation once settled
	m_pairLoadsThisStep.resize(0);
	m_pairLoadsIndexed = false;  // indexed on the first miss: a step whose groups kept their order needs none
	m_pairLoadCursor = 0;
}

const btLayeredPasses::btPairLoad* btLayeredPasses::findPairLoad(const void* manifold, int hint)
{
	const int n = m_pairLoadsLastStep.size();
	if (hint >= 0 && hint < n && m_pairLoadsLastStep[hint].m_manifold == manifold) return &m_pairLoadsLastStep[hint];
	// An open-addressing table of last step's records by manifold (each manifold is recorded once
	// a step), built on the first miss: a power of two of at least twice the records, so a probe
	// sequence ends at an empty slot (-1).
	const auto slotOf = [](const void* key, int mask) {
		const unsigned long long bits = static_cast<unsigned long long>(reinterpret_cast<uintptr_t>(key));
		return int(((bits >> 4) * 0x9E3779B97F4A7C15ull) >> 33) & mask;
	};
	if (!m_pairLoadsIndexed)
	{
		int size = 16;
		while (size < 2 * n) size *= 2;
		m_pairLoadTable.resize(size);
		for (int i = 0; i < size; ++i) m_pairLoadTable[i] = -1;
		for (int i = 0; i < n; ++i)
		{
			int slot = slotOf(m_pairLoadsLastStep[i].m_manifold, size - 1);
			while (m_pairLoadTable[slot] >= 0) slot = (slot + 1) & (size - 1);
			m_pairLoadTable[slot] = i;
		}
		m_pairLoadsIndexed = true;
	}
	const int mask = m_pairLoadTable.size() - 1;
	for (int slot = slotOf(manifold, mask);; slot = (slot + 1) & mask)
	{
		const int i = m_pairLoadTable[slot];
		if (i < 0) return 0;
		if (m_pairLoadsLastStep[i].m_manifold == manifold) return &m_pairLoadsLastStep[i];
	}
}

// ---------------------------------------------------------------------------------------------------
// D23: sliding composites (btSlidingComposite.h).

namespace
{
/// A friction impulse within this share of its Coulomb bound mu N counts as at the bound.
const btScalar kAtCoulombLimit = btScalar(0.99);
}  // namespace

void btLayeredPasses::markSlipsAtSetup(const btSolverPools& pools, btScalar speed)
{
	m_slipsAtSetup.resize(pools.m_frictions.size());
	for (int i = 0; i < pools.m_frictions.size(); ++i)
		m_slipsAtSetup[i] = btFabs(btRowSlipAtSetup(pools.m_frictions[i], pools.m_bodies)) > speed ? 1 : 0;
}

int btLayeredPasses::freeIndexOf(int layer, int node) const
{
	const int numFree = layer < m_layers->getNumLayers() ? m_layers->getNumFreeBodies(layer) : 0;
	for (int i = 0; i < numFree; ++i)
		if (m_layers->getFreeBody(layer, i) == node) return i;
	return -1;
}

void btLayeredPasses::formComposites(int layer, const btSolverPools& pools, btScalar slip)
{
	btAlignedObjectArray<btSolverBody>& bodies = pools.m_bodies;
	const auto dynamicBody = [&](int id) -> const btRigidBody* {
		const btRigidBody* rb = bodies[id].m_originalBody;
		return (rb && rb->getInvMass() > btScalar(0)) ? rb : 0;
	};
	markFixated(layer, 1);
	const int first = m_composites.size();
	for (int r = m_frictionStart[layer]; r < m_frictionStart[layer + 1]; ++r)
	{
		const int index = m_frictionRows[r];
		const btSolverConstraint& c = pools.m_frictions[index];
		if (!m_slipsAtSetup[index] || c.m_frictionIndex < 0 || c.m_frictionIndex >= pools.m_contacts.size()) continue;
		const btSolverConstraint& contact = pools.m_contacts[c.m_frictionIndex];
		const btScalar normal = contact.m_appliedImpulse;
		if (!(normal > btScalar(0))) continue;
		// One end free in this layer, the other its support (fixated here, or static).
		const bool lowA = m_fixated[c.m_solverBodyIdA] != 0 || !dynamicBody(c.m_solverBodyIdA);
		const bool lowB = m_fixated[c.m_solverBodyIdB] != 0 || !dynamicBody(c.m_solverBodyIdB);
		if (lowA == lowB) continue;
		const int id = lowA ? c.m_solverBodyIdB : c.m_solverBodyIdA;
		const btRigidBody* rb = dynamicBody(id);
		const int node = m_nodeOfSolverBody[id];
		// A body already carried by a composite below it moves with that composite.
		if (!rb || node < 0 || compositeOf(id) >= 0 || m_carried[id]) continue;
		// A body in a joint moves with what it is jointed to, which the composite does not model.
		if (inJoint(id)) continue;
		// Sliding: the friction at its Coulomb bound and still slipping after the global pass.
		if (!(btFabs(c.m_appliedImpulse) >= kAtCoulombLimit * c.m_friction * normal)) continue;
		if (!(btFabs(btRowVelocityError(c, bodies)) > slip)) continue;

		btSlidingComposite comp;
		comp.m_base = id;
		comp.m_node = node;
		comp.m_layer = layer;
		const btVector3& n = contact.m_contactNormal1.isZero() ? contact.m_contactNormal2 : contact.m_contactNormal1;
		comp.m_normal = n.length2() > SIMD_EPSILON ? n.normalized() : btVector3(0, 1, 0);
		// The sub-stack: every dynamic body above the base through contact rows, layer by layer.
		comp.m_firstMember = m_compositeMembers.size();
		m_compositeMembers.push_back(id);
		m_inComposite[id] = 1;
		btScalar mass = btScalar(1) / rb->getInvMass();
		const int height = m_layers->getHeight(node);
		for (int k = layer + 1; k < m_numLayers; ++k)
			for (int i = m_contactStart[k]; i < m_contactStart[k + 1]; ++i)
			{
				const btSolverConstraint& row = pools.m_contacts[m_contactRows[i]];
				const int a = row.m_solverBodyIdA, b = row.m_solverBodyIdB;
				if (m_inComposite[a] == m_inComposite[b]) continue;
				const int up = m_inComposite[a] ? b : a;
				const btRigidBody* upper = dynamicBody(up);
				const int upNode = m_nodeOfSolverBody[up];
				if (!upper || upNode < 0 || inJoint(up) || m_layers->getHeight(upNode) <= height) continue;
				// Resting on it: the contact carried a load last step (a body landing now is an impact).
				const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
				if (!cp || !(cp->m_appliedImpulse > btScalar(0))) continue;
				m_inComposite[up] = 1;
				m_compositeMembers.push_back(up);
				mass += btScalar(1) / upper->getInvMass();
			}
		comp.m_numMembers = m_compositeMembers.size() - comp.m_firstMember;
		for (int j = 0; j < comp.m_numMembers; ++j)
		{
			m_inComposite[m_compositeMembers[comp.m_firstMember + j]] = 0;
			m_carried[m_compositeMembers[comp.m_firstMember + j]] = 1;
		}
		if (comp.m_numMembers < 2)
		{
			// Nothing rests on it: a body sliding alone is solved as it is.
			m_compositeMembers.resize(comp.m_firstMember);
			continue;
		}
		comp.m_massRatio = mass * rb->getInvMass();
		// The sub-stack sticks: it starts at its momentum's velocity across the support.
		btEqualizeAcross(bodies, &m_compositeMembers[comp.m_firstMember], comp.m_numMembers, comp.m_normal);
		btSolverBody& base = bodies[id];
		comp.m_velocityBefore = base.m_linearVelocity + base.m_externalForceImpulse + base.internalGetDeltaLinearVelocity();
		comp.m_savedInvMass = base.internalGetInvMass();
		m_compositeOf[id] = m_composites.size();
		m_composites.push_back(comp);
	}
	markFixated(layer, 0);
	for (int i = first; i < m_composites.size(); ++i) m_active.push_back(i);
}

btVector3 btLayeredPasses::compositeShift(int layer, const btSlidingComposite& comp, const btSolverPools& pools)
{
	// The impulse the layer's rows gave the base since its pass began, across its support, taken by
	// the whole composite (m/s).
	btVector3 impulse(0, 0, 0);
	int row = 0;
	visitLayerRows(layer, pools, [&](btSolverConstraint& c, btSolverRowKind) {
		const btScalar change = btScalar(c.m_appliedImpulse) - m_impulseBefore[row++];
		if (c.m_solverBodyIdA == comp.m_base) impulse += c.m_contactNormal1 * change;
		else if (c.m_solverBodyIdB == comp.m_base) impulse += c.m_contactNormal2 * change;
	});
	btVector3 shift = impulse * (pools.m_bodies[comp.m_base].m_originalBody->getInvMass() / comp.m_massRatio);
	return shift - comp.m_normal * shift.dot(comp.m_normal);
}

void btLayeredPasses::carryComposites(int layer, const btSolverPools& pools)
{
	for (int i = 0; i < m_active.size(); ++i)
	{
		btSlidingComposite& comp = m_composites[m_active[i]];
		btSolverBody& base = pools.m_bodies[comp.m_base];
		// The base and the sub-stack move by the impulse over M (momentum kept; the bodies above
		// then have nothing left to drag, and hand down no reaction for it).
		const btVector3 shift = compositeShift(layer, comp, pools);
		btSetDeltaAcross(base, comp.m_velocityBefore - (base.m_linearVelocity + base.m_externalForceImpulse) + shift, comp.m_normal);
		for (int j = 1; j < comp.m_numMembers; ++j) pools.m_bodies[m_compositeMembers[comp.m_firstMember + j]].internalGetDeltaLinearVelocity() += shift;
		m_compositeOf[comp.m_base] = -1;
	}
	m_active.resize(0);
}

void btLayeredPasses::activateComposites(int layer, const btSolverPools& pools, btScalar tolerance)
{
	m_active.resize(0);
	for (int i = 0; i < m_composites.size(); ++i)
	{
		btSlidingComposite& comp = m_composites[i];
		if (comp.m_layer != layer) continue;
		const int local = freeIndexOf(layer, comp.m_node);
		comp.m_local = local;
		// The load handed to the base across its support is what the composite did not predict:
		// the sub-stack did not move with it (a body above slid), so it is solved alone.
		btVector3 load = local >= 0 ? m_before[local].m_loadLinear : btVector3(0, 0, 0);
		load -= comp.m_normal * load.dot(comp.m_normal);
		comp.m_held = local >= 0 && load.length() <= tolerance;
		if (!comp.m_held) continue;
		comp.m_savedInvMass = pools.m_bodies[comp.m_base].internalGetInvMass();
		m_compositeOf[comp.m_base] = i;
		m_active.push_back(i);
	}
}

void btLayeredPasses::shareCompositeMotion(int layer, const btSolverPools& pools)
{
	for (int a = 0; a < m_active.size(); ++a)
	{
		btSlidingComposite& comp = m_composites[m_active[a]];
		comp.m_shift.setZero();
		const int local = comp.m_local;  // held composites have one (activateComposites)
		// The re-solve's impulse (its load transfer with m_B, its friction sweeps with M) moves the
		// whole composite: the base by it over M after its load, the sub-stack when the layer stands.
		comp.m_shift = compositeShift(layer, comp, pools);
		btSetDeltaAcross(pools.m_bodies[comp.m_base], m_before[local].m_deltaLinear + m_before[local].m_loadLinear + comp.m_shift, comp.m_normal);
	}
}

void btLayeredPasses::deactivateComposites(bool moveMembers, const btSolverPools& pools)
{
	for (int a = 0; a < m_active.size(); ++a)
	{
		btSlidingComposite& comp = m_composites[m_active[a]];
		m_compositeOf[comp.m_base] = -1;
		if (!moveMembers)
		{
			comp.m_held = false;  // a rejected layer keeps its state from before its load
			continue;
		}
		for (int j = 1; j < comp.m_numMembers; ++j)
			pools.m_bodies[m_compositeMembers[comp.m_firstMember + j]].internalGetDeltaLinearVelocity() += comp.m_shift;
	}
	m_active.resize(0);
}

int btLayeredPasses::finishComposites(const btSolverPools& pools)
{
	for (int i = 0; i < m_composites.size(); ++i)
	{
		const btSlidingComposite& comp = m_composites[i];
		if (comp.m_held) btEqualizeAcross(pools.m_bodies, &m_compositeMembers[comp.m_firstMember], comp.m_numMembers, comp.m_normal);
	}
	return m_composites.size();
}

bool btLayeredPasses::gatherTippingMembers(int layer, int id, int mark, const btSolverPools& pools)
{
	btAlignedObjectArray<btSolverBody>& bodies = pools.m_bodies;
	if (m_tipOf.size() != bodies.size())
	{
		m_tipOf.resize(bodies.size());
		for (int i = 0; i < bodies.size(); ++i) m_tipOf[i] = 0;
	}
	if (!m_rowsOfBodyBuilt) buildRowsOfBody(pools);
	if (!m_tipEligible[id] || m_tipOf[id] != 0 || m_nodeOfSolverBody[id] < 0) return false;
	const btRigidBody* baseBody = bodies[id].m_originalBody;
	const btVector3 g = baseBody->getGravity();
	if (!(g.length2() > SIMD_EPSILON)) return false;
	const btVector3 up = -g.normalized();
	const int first = m_tipMembers.size();
	// A contact row on which `upper` rests on `lower`: it pushes now, along a normal within 60
	// degrees of up into the upper body.
	const auto restsOn = [&](const btSolverConstraint& row, int upper) {
		if (!(row.m_appliedImpulse > btScalar(0))) return false;
		const btVector3& n = row.m_solverBodyIdA == upper ? row.m_contactNormal1 : row.m_contactNormal2;
		return n.dot(up) >= btScalar(0.5);
	};
	m_tipMembers.push_back(id);
	m_tipOf[id] = mark;
	// The rows above the layer in order (by layer, then Bullet's order), each looked at once, and
	// only if it touches a member: a member's rows are queued from the position where it joined.
	const int aboveBegin = m_contactStart[btMin(layer + 1, m_numLayers)];
	btAlignedObjectArray<int>& queue = m_tipQueue;
	queue.resize(0);
	// Only the rows on which the other body is the higher one: a member can carry nothing through
	// any other row (the walk would skip it).
	const auto enqueueRows = [&](int body, int from) {
		for (int p = m_rowsOfBodyStart[body]; p < m_rowsOfBodyStart[body + 1]; ++p)
		{
			const int r = m_rowsOfBody[p];
			const int upper = m_rowUpper[r];
			if (r < from || upper < 0 || upper == body) continue;
			queue.push_back(r);
			std::push_heap(&queue[0], &queue[0] + queue.size(), std::greater<int>());
		}
	};
	enqueueRows(id, aboveBegin);
	bool clash = false;
	int previous = -1;
	while (queue.size() && !clash)
	{
		std::pop_heap(&queue[0], &queue[0] + queue.size(), std::greater<int>());
		const int r = queue[queue.size() - 1];
		queue.pop_back();
		if (r == previous) continue;  // queued twice
		previous = r;
		// Queued by its lower body, a member: the higher one joins if it rests on it.
		const int upper = m_rowUpper[r];
		if (m_tipOf[upper] == mark) continue;  // already a member
		if (!m_tipEligible[upper] || !restsOn(pools.m_contacts[m_contactRows[r]], upper)) continue;
		if (m_tipOf[upper] != 0)
		{
			clash = true;  // it rests on another tipping body too
			break;
		}
		m_tipOf[upper] = mark;
		m_tipMembers.push_back(upper);
		enqueueRows(upper, r + 1);
	}
	// Only what rests on the composite alone: a body also resting on something outside it (and,
	// in turn, what rests on that body) is left out. Members are in order of height.
	for (int j = first + 1; j < m_tipMembers.size() && !clash; ++j)
	{
		const int member = m_tipMembers[j];
		// Its supports are the contact rows of the layer below its height; a row to another member
		// is skipped without reading it.
		visitBodyRows(member, m_layers->getHeight(m_nodeOfSolverBody[member]) - 1, pools, [&](const btSolverConstraint& row, int r) {
			if (m_rowUpper[r] == member && m_tipOf[m_rowLower[r]] == mark) return;
			const int other = row.m_solverBodyIdA == member ? row.m_solverBodyIdB : row.m_solverBodyIdA;
			if (m_tipOf[other] != mark && restsOn(row, member)) m_tipOf[member] = -mark;  // left out (kept marked until the layer ends, then cleared)
		});
	}
	int kept = first;
	for (int j = first; j < m_tipMembers.size(); ++j)
	{
		const int member = m_tipMembers[j];
		if (m_tipOf[member] == mark)
			m_tipMembers[kept++] = member;
		else
			m_tipOf[member] = 0;
	}
	m_tipMembers.resize(kept);
	if (clash || kept - first < 2)
	{
		for (int j = first; j < m_tipMembers.size(); ++j) m_tipOf[m_tipMembers[j]] = 0;
		m_tipMembers.resize(first);
		return false;
	}
	return true;
}

void btLayeredPasses::buildRowsOfBody(const btSolverPools& pools)
{
	const int numBodies = pools.m_bodies.size();
	const int numPositions = m_contactStart[m_numLayers];
	m_rowsOfBodyStart.resize(numBodies + 1);
	for (int i = 0; i <= numBodies; ++i) m_rowsOfBodyStart[i] = 0;
	for (int r = 0; r < numPositions; ++r)
	{
		const btSolverConstraint& row = pools.m_contacts[m_contactRows[r]];
		++m_rowsOfBodyStart[row.m_solverBodyIdA + 1];
		if (row.m_solverBodyIdB != row.m_solverBodyIdA) ++m_rowsOfBodyStart[row.m_solverBodyIdB + 1];
	}
	for (int i = 0; i < numBodies; ++i) m_rowsOfBodyStart[i + 1] += m_rowsOfBodyStart[i];
	m_rowsOfBody.resize(m_rowsOfBodyStart[numBodies]);
	btAlignedObjectArray<int>& cursor = m_scratchCursor;
	cursor.resize(numBodies);
	for (int i = 0; i < numBodies; ++i) cursor[i] = m_rowsOfBodyStart[i];
	m_rowUpper.resize(numPositions);
	m_rowLower.resize(numPositions);
	for (int r = 0; r < numPositions; ++r)  // ascending, so each body's positions are too
	{
		const btSolverConstraint& row = pools.m_contacts[m_contactRows[r]];
		m_rowsOfBody[cursor[row.m_solverBodyIdA]++] = r;
		if (row.m_solverBodyIdB != row.m_solverBodyIdA) m_rowsOfBody[cursor[row.m_solverBodyIdB]++] = r;
		const int nodeA = m_nodeOfSolverBody[row.m_solverBodyIdA], nodeB = m_nodeOfSolverBody[row.m_solverBodyIdB];
		const int heightA = nodeA < 0 ? -1 : m_layers->getHeight(nodeA), heightB = nodeB < 0 ? -1 : m_layers->getHeight(nodeB);
		const bool ordered = nodeA >= 0 && nodeB >= 0 && heightA != heightB;
		m_rowUpper[r] = !ordered ? -1 : (heightA > heightB ? row.m_solverBodyIdA : row.m_solverBodyIdB);
		m_rowLower[r] = !ordered ? -1 : (heightA > heightB ? row.m_solverBodyIdB : row.m_solverBodyIdA);
	}
	m_tipEligible.resize(numBodies);
	for (int i = 0; i < numBodies; ++i)
	{
		const btSolverBody& b = pools.m_bodies[i];
		const btRigidBody* rb = b.m_originalBody;
		m_tipEligible[i] = rb && rb->getInvMass() > btScalar(0) && !inJoint(i) && b.m_linearFactor == btVector3(1, 1, 1) &&
						   b.m_angularFactor == btVector3(1, 1, 1);
	}
	m_rowsOfBodyBuilt = true;
}

bool btLayeredPasses::membersOutsideSupport(int layer, int id, int first, const btSolverPools& pools)
{
	// Statics of the composite as one rigid body: its weight acts through its centre of mass.
	btScalar mass = 0;
	btVector3 centre(0, 0, 0);
	for (int j = first; j < m_tipMembers.size(); ++j)
	{
		const btRigidBody* rb = pools.m_bodies[m_tipMembers[j]].m_originalBody;
		mass += btScalar(1) / rb->getInvMass();
		centre += rb->getCenterOfMassPosition() / rb->getInvMass();
	}
	centre /= mass;
	const btRigidBody* rb = pools.m_bodies[id].m_originalBody;
	return lineOutsideSupport(layer, id, rb->getGravity() * mass, centre - rb->getCenterOfMassPosition(), btScalar(0), pools);
}

bool btLayeredPasses::tipWithMembers(int layer, int local, int sweeps, const btWeightPassParams& weight, const btSolverPools& pools, int* sweepsRun,
									 bool impact, bool slide)
{
	const int id = m_solverBodyOfNode[m_layers->getFreeBody(layer, local)];
	const int first = m_tipMembers.size();
	const int mark = m_tipFirst.size() + 1;
	// D27: an impact's momentum, not the composite's weight, decides whether it turns (the guard
	// found the load outside the support already). D29: a sliding composite needs no statics (it
	// is solved as one rigid body; whether it also turns is the solve's answer).
	bool kept = gatherTippingMembers(layer, id, mark, pools) && (slide || impact || membersOutsideSupport(layer, id, first, pools));
	if (kept)
	{
		gatherSupportRows(layer, pools);
		const int slot = m_freeSlot[layer] + local;
		const int numRows = m_supportEnd[slot] - m_supportBegin[slot];
		// Each member's state before (restored if the solve is not kept or the layer is rejected),
		// then the loads rejected layers gave back: they are the members' momentum too.
		m_tipSaved.resize(m_tipMembers.size());
		for (int j = first; j < m_tipMembers.size(); ++j)
		{
			btSolverBody& member = pools.m_bodies[m_tipMembers[j]];
			m_tipSaved[j].m_deltaLinear = member.internalGetDeltaLinearVelocity();
			m_tipSaved[j].m_deltaAngular = member.internalGetDeltaAngularVelocity();
			member.internalGetDeltaLinearVelocity() += m_discardedLinear[m_tipMembers[j]];
			member.internalGetDeltaAngularVelocity() += m_discardedAngular[m_tipMembers[j]];
		}
		// The body's support rows start again from where the layer pass found them: their
		// re-solve did not carry the load alone (the guard's reason to be here), so its result is
		// no starting point; the composite solves them.
		btScalar resolved[btTippingCompositeMaxRows];
		const bool fits = numRows > 0 && numRows <= btTippingCompositeMaxRows;
		for (int r = 0; fits && r < numRows; ++r) resolved[r] = m_transferRows[m_supportBegin[slot] + r].m_row->m_appliedImpulse;
		if (fits)
		{
			// m_impulseBefore is in visitLayerRows' order: joints (layer 0), contacts, frictions.
			btSolverBody& base = pools.m_bodies[id];
			const btLoadTransferRow* support = &m_transferRows[m_supportBegin[slot]];
			const int contactsFrom = hasJoints(layer, pools) ? pools.m_joints.size() : 0;
			const int frictionsFrom = contactsFrom + m_contactStart[layer + 1] - m_contactStart[layer];
			for (int r = 0; r < numRows; ++r)
			{
				btSolverConstraint& c = *support[r].m_row;
				const btScalar before = m_impulseBefore[(support[r].m_contact ? contactsFrom : frictionsFrom) + support[r].m_position];
				const btScalar change = btScalar(c.m_appliedImpulse) - before;
				base.internalApplyImpulse((support[r].m_sideA ? c.m_contactNormal1 : c.m_contactNormal2) * base.internalGetInvMass(),
										  support[r].m_sideA ? c.m_angularComponentA : c.m_angularComponentB, -change);
				c.m_appliedImpulse = before;
			}
		}
		int run = 0;
		kept = fits && btSolveTippingComposite(pools.m_bodies, &m_tipMembers[first], m_tipMembers.size() - first,
													  &m_transferRows[m_supportBegin[slot]], numRows, pools.m_contacts, sweeps,
													  weight.m_convergedSpeed, &run, slide);
		*sweepsRun += run;
		// The guard's bound for a body that tips (D16), on every member: the composite leaves none
		// faster than it began the step (last step's velocity and this step's gravity) by more
		// than m_tipGain steps of free fall. A composite that would has taken in a load its
		// support could not carry (hostile worlds: a 66 g base under a 43 kg body), as a lone
		// body's re-solve that the guard rejects.
		const btScalar gain = weight.m_tipGain * pools.m_bodies[id].m_originalBody->getGravity().length() * weight.m_timeStep;
		for (int j = first; kept && j < m_tipMembers.size(); ++j)
		{
			btSolverBody& member = pools.m_bodies[m_tipMembers[j]];
			const btVector3 base = member.m_linearVelocity + member.m_externalForceImpulse;
			if (!((base + member.internalGetDeltaLinearVelocity()).length() <= base.length() + gain)) kept = false;
		}
		// D29: a sliding composite only where each member can stick to what carries it (the
		// merge holds them together whatever their friction).
		if (kept && slide) kept = membersStick(first, mark, weight.m_slack * pools.m_bodies[id].m_originalBody->getGravity().length() * weight.m_timeStep, pools);
		if (!kept)
		{
			restoreTipMembers(first, m_tipMembers.size(), pools);
			for (int r = 0; fits && r < numRows; ++r) m_transferRows[m_supportBegin[slot] + r].m_row->m_appliedImpulse = resolved[r];
		}
	}
	if (!kept)
	{
		for (int j = first; j < m_tipMembers.size(); ++j) m_tipOf[m_tipMembers[j]] = 0;
		m_tipMembers.resize(first);
		m_tipSaved.resize(first);
		return false;
	}
	m_tipFirst.push_back(first);
	m_tipBase.push_back(local);
	m_tipSlides.push_back(slide ? 1 : 0);
	return true;
}

void btLayeredPasses::rejectIslands(int layer, bool perIsland)
{
	const int numFree = m_layers->getNumFreeBodies(layer);
	if (!perIsland)
	{
		for (int i = 0; i < numFree; ++i) m_rejectLocal[i] = 1;
		return;
	}
	// Every free body of the layer in a rejected body's island (its connected component of the
	// contact graph: Bullet's simulation island; islands Bullet batched into one solve are others).
	m_rejectedComponents.resize(0);
	for (int i = 0; i < numFree; ++i)
		if (m_rejectLocal[i]) m_rejectedComponents.push_back(m_layers->getComponent(m_layers->getFreeBody(layer, i)));
	for (int i = 0; i < numFree; ++i)
	{
		const int component = m_layers->getComponent(m_layers->getFreeBody(layer, i));
		for (int c = 0; c < m_rejectedComponents.size() && !m_rejectLocal[i]; ++c)
			if (m_rejectedComponents[c] == component) m_rejectLocal[i] = 1;
	}
}

void btLayeredPasses::restoreTipMembers(int first, int end, const btSolverPools& pools)
{
	for (int j = first; j < end; ++j)
	{
		btSolverBody& member = pools.m_bodies[m_tipMembers[j]];
		member.internalGetDeltaLinearVelocity() = m_tipSaved[j].m_deltaLinear;
		member.internalGetDeltaAngularVelocity() = m_tipSaved[j].m_deltaAngular;
	}
}
