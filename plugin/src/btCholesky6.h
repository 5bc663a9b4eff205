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
		for (int i = 0; i < 6; ++i)
		{
			if (!jacobiScaled) continue;
			if (!(A[i][i] > btScalar(0))) return false;
			m_scale[i] = btScalar(1) / btSqrt(A[i][i]);
		}
		for (int i = 0; i < 6; ++i)
			for (int j = 0; j <= i; ++j)
			{
				btScalar sum = jacobiScaled ? A[i][j] * m_scale[i] * m_scale[j] : A[i][j];
				if (i == j) sum += shift;
				for (int k = 0; k < j; ++k) sum -= m_L[i][k] * m_L[j][k];
				if (i == j)
				{
					if (!(sum > minPivot)) return false;
					m_L[i][i] = btSqrt(sum);
				}
				else
					m_L[i][j] = sum / m_L[j][j];
			}
		m_scaled = jacobiScaled;
		return true;
	}

	/// x = (A + shift I)^-1 b with the factor above.
	void solve(const btScalar b[6], btScalar x[6]) const
	{
		btScalar y[6];
		for (int i = 0; i < 6; ++i)
		{
			btScalar sum = m_scaled ? b[i] * m_scale[i] : b[i];
			for (int k = 0; k < i; ++k) sum -= m_L[i][k] * y[k];
			y[i] = sum / m_L[i][i];
		}
		for (int i = 5; i >= 0; --i)
		{
			btScalar sum = y[i];
			for (int k = i + 1; k < 6; ++k) sum -= m_L[k][i] * x[k];
			x[i] = sum / m_L[i][i];
		}
		if (m_scaled)
			for (int i = 0; i < 6; ++i) x[i] *= m_scale[i];
	}

private:
	bool m_scaled = false;
};

#endif  // BT_SHOCK_PROPAGATION_CHOLESKY6_H
