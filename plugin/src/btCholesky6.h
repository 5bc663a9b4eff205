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

#ifndef BT_SHOCK_PROPAGATION_CHOLESKY6_H
#define BT_SHOCK_PROPAGATION_CHOLESKY6_H

#include "LinearMath/btScalar.h"

// The loops below are unrolled whole (and so are the sums of J J^T over a body's support rows,
// btShockPredictor::addRow and addSupportRows): their trip counts then are constants, the factor
// and the substitutions run without loop control, and the processor overlaps their independent
// entries around the chain of divisions and roots (a factor and two solves on one core of the
// development machine: 240 to 134 ns in float, 325 to 152 ns in double). The operations and their
// order are the loops' own, so the results are too, bit for bit.
#if defined(__GNUC__) || defined(__clang__)
#define BT_CHOLESKY6_UNROLL _Pragma("GCC unroll 6")
#else
#define BT_CHOLESKY6_UNROLL
#endif

/// Cholesky factor of a symmetric positive 6 x 6 matrix, the normal equations of one body's rows
/// (load transfer, D16; support block, D19). Private to the plugin.
struct btCholesky6
{
	btScalar m_L[6][6] = {};
	btScalar m_scale[6] = {1, 1, 1, 1, 1, 1};

	/// Factors A + shift I. jacobiScaled: factor D^-1/2 A D^-1/2 (D = diag A) instead, so metres and
	/// radians weigh alike. False if a pivot is not above minPivot (or, scaled, a diagonal is not
	/// positive).
	bool factor(const btScalar A[6][6], btScalar shift, btScalar minPivot, bool jacobiScaled)
	{
		// Formed in locals and stored once: written through the members, every entry was stored and
		// loaded again (A might alias them), on the chain of dependent divisions and roots.
		btScalar scale[6] = {1, 1, 1, 1, 1, 1};
		BT_CHOLESKY6_UNROLL
		for (int i = 0; i < 6; ++i)
		{
			if (!jacobiScaled) continue;
			if (!(A[i][i] > btScalar(0))) return false;
			scale[i] = btScalar(1) / btSqrt(A[i][i]);
		}
		btScalar L[6][6] = {};
		BT_CHOLESKY6_UNROLL
		for (int i = 0; i < 6; ++i)
			BT_CHOLESKY6_UNROLL
			for (int j = 0; j <= i; ++j)
			{
				btScalar sum = jacobiScaled ? A[i][j] * scale[i] * scale[j] : A[i][j];
				if (i == j) sum += shift;
				BT_CHOLESKY6_UNROLL
				for (int k = 0; k < j; ++k) sum -= L[i][k] * L[j][k];
				if (i == j)
				{
					if (!(sum > minPivot)) return false;
					L[i][i] = btSqrt(sum);
				}
				else
					L[i][j] = sum / L[j][j];
			}
		BT_CHOLESKY6_UNROLL
		for (int i = 0; i < 6; ++i)
		{
			if (jacobiScaled) m_scale[i] = scale[i];
			BT_CHOLESKY6_UNROLL
			for (int j = 0; j <= i; ++j) m_L[i][j] = L[i][j];
		}
		m_scaled = jacobiScaled;
		return true;
	}

	/// x = (A + shift I)^-1 b with the factor above.
	void solve(const btScalar b[6], btScalar x[6]) const
	{
		// Both substitutions in locals, x written once at the end: through x (which might alias
		// the factor) each unknown went to memory and back on the substitution's dependent chain.
		btScalar y[6], z[6];
		BT_CHOLESKY6_UNROLL
		for (int i = 0; i < 6; ++i)
		{
			btScalar sum = m_scaled ? b[i] * m_scale[i] : b[i];
			BT_CHOLESKY6_UNROLL
			for (int k = 0; k < i; ++k) sum -= m_L[i][k] * y[k];
			y[i] = sum / m_L[i][i];
		}
		BT_CHOLESKY6_UNROLL
		for (int i = 5; i >= 0; --i)
		{
			btScalar sum = y[i];
			BT_CHOLESKY6_UNROLL
			for (int k = i + 1; k < 6; ++k) sum -= m_L[k][i] * z[k];
			z[i] = sum / m_L[i][i];
		}
		BT_CHOLESKY6_UNROLL
		for (int i = 0; i < 6; ++i) x[i] = m_scaled ? z[i] * m_scale[i] : z[i];
	}

private:
	bool m_scaled = false;
};

#endif  // BT_SHOCK_PROPAGATION_CHOLESKY6_H
