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

#ifndef BT_SHOCK_PROPAGATION_EXPORT_H
#define BT_SHOCK_PROPAGATION_EXPORT_H

/// BT_SHOCK_PROPAGATION_API marks the public classes. The library is compiled with
/// -fvisibility=hidden, so the shared library exports these classes and nothing else; in a
/// static library or in an app the mark changes nothing. GCC and Clang (the platforms Debian's
/// Bullet is built for); elsewhere it is empty.
#if defined(__GNUC__) || defined(__clang__)
#define BT_SHOCK_PROPAGATION_API __attribute__((visibility("default")))
#else
#define BT_SHOCK_PROPAGATION_API
#endif

#endif  // BT_SHOCK_PROPAGATION_EXPORT_H
