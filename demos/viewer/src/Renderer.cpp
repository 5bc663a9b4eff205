#include "viewer/Renderer.h"

#include "Gl.h"

#include <BulletCollision/CollisionShapes/btShapeHull.h>

#include <stdexcept>
#include <string>
#include <unordered_map>

namespace viewer
{
namespace
{
const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 uViewProj;
uniform mat4 uModel;
uniform vec3 uScale;
out vec3 vWorld;
out vec3 vNormal;
out vec3 vLocal;
out vec3 vLocalNormal;
void main()
{
	vLocal = aPos * uScale;
	vLocalNormal = aNormal;
	vec4 world = uModel * vec4(vLocal, 1.0);
	vWorld = world.xyz;
	vNormal = mat3(uModel) * aNormal;
	gl_Position = uViewProj * world;
}
)";

// Lighting is white (ambient + two directional lights + sky), so shading scales a body's colour
// and keeps its hue: the layer colour of a body can be read back from any of its pixels.
const char* kFragmentShader = R"(#version 330 core
in vec3 vWorld;
in vec3 vNormal;
in vec3 vLocal;
in vec3 vLocalNormal;
uniform vec3 uColour;
uniform vec3 uScale;
uniform int uMode;   // 0 body, 1 ground (checkered), 2 unlit
uniform int uEdges;  // 1: darken a box's edges (about one pixel wide)
uniform float uAlpha;
out vec4 fragColour;
void main()
{
	if (uMode == 2) { fragColour = vec4(uColour, 1.0); return; }
	vec3 n = normalize(vNormal);
	float key = max(dot(n, normalize(vec3(0.45, 0.8, 0.6))), 0.0);
	float fill = max(dot(n, normalize(vec3(-0.6, 0.3, -0.35))), 0.0);
	float light = 0.28 + 0.55 * key + 0.17 * fill + 0.1 * (0.5 + 0.5 * n.y);
	vec3 c = uColour;
	if (uMode == 1)
	{
		vec2 cell = floor(vWorld.xz);
		c *= mix(0.86, 1.0, mod(cell.x + cell.y, 2.0));
	}
	if (uEdges == 1)
	{
		// Distance to the face's border in pixels along the two in-face axes.
		vec3 d = (uScale - abs(vLocal)) / max(fwidth(vLocal), vec3(1e-7));
		vec3 faceAxis = step(vec3(0.5), abs(vLocalNormal));
		d += faceAxis * 1e9;
		float edge = min(d.x, min(d.y, d.z));
		c *= mix(0.45, 1.0, smoothstep(0.4, 1.4, edge));
	}
	fragColour = vec4(c * light, uAlpha);
}
)";

unsigned compile(unsigned type, const char* source)
{
	const GLuint shader = glCreateShader(type);
	glShaderSource(shader, 1, &source, nullptr);
	glCompileShader(shader);
	GLint ok = 0;
	glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
	if (!ok)
	{
		char log[2048] = {0};
		glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
		glDeleteShader(shader);
		throw std::runtime_error(std::string("viewer shader does not compile: ") + log);
	}
	return shader;
}

Mat4 toMat4(const btTransform& t)
{
	btScalar gl[16];
	t.getOpenGLMatrix(gl);
	Mat4 m;
	for (int i = 0; i < 16; ++i) m.m[i] = float(gl[i]);
	return m;
}

/// Unit cube [-1, 1]^3, four vertices (position, normal) per face.
void cubeMesh(std::vector<float>& vertices, std::vector<unsigned>& indices)
{
	for (int axis = 0; axis < 3; ++axis)
	{
		for (int sign = -1; sign <= 1; sign += 2)
		{
			const int u = (axis + 1) % 3, v = (axis + 2) % 3;
			const unsigned base = unsigned(vertices.size() / 6);
			const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
			for (const auto& c : corners)
			{
				float p[3], n[3] = {0, 0, 0};
				p[axis] = float(sign);
				p[u] = c[0];
				p[v] = c[1];
				n[axis] = float(sign);
				vertices.insert(vertices.end(), {p[0], p[1], p[2], n[0], n[1], n[2]});
			}
			// Counter-clockwise seen from outside.
			if (sign > 0)
				indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
			else
				indices.insert(indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
		}
	}
}

/// Flat-shaded triangles (position, normal) of a convex shape's hull.
std::vector<float> hullMesh(const btConvexShape& shape)
{
	std::vector<float> out;
	btShapeHull hull(&shape);
	if (!hull.buildHull(shape.getMargin())) return out;
	const btVector3* v = hull.getVertexPointer();
	const unsigned* idx = hull.getIndexPointer();
	for (int t = 0; t < hull.numTriangles(); ++t)
	{
		const btVector3& a = v[idx[3 * t]];
		const btVector3& b = v[idx[3 * t + 1]];
		const btVector3& c = v[idx[3 * t + 2]];
		btVector3 n = (b - a).cross(c - a);
		if (n.length2() < SIMD_EPSILON) continue;
		n.normalize();
		for (const btVector3* p : {&a, &b, &c})
			out.insert(out.end(), {float(p->x()), float(p->y()), float(p->z()), float(n.x()), float(n.y()), float(n.z())});
	}
	return out;
}

void setVertexLayout()
{
	glEnableVertexAttribArray(0);
	glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
	glEnableVertexAttribArray(1);
	glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
}

/// Opacity of static bodies other than the ground.
const float kStaticAlpha = 0.35f;

enum ShaderMode
{
	kModeBody = 0,
	kModeGround = 1,
	kModeUnlit = 2
};
}  // namespace

Rgb backgroundColour() { return {0.80f, 0.86f, 0.92f}; }
Rgb groundColour() { return {0.60f, 0.66f, 0.56f}; }

Renderer::Renderer()
{
	const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
	const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
	m_program = glCreateProgram();
	glAttachShader(m_program, vs);
	glAttachShader(m_program, fs);
	glLinkProgram(m_program);
	glDeleteShader(vs);
	glDeleteShader(fs);
	GLint ok = 0;
	glGetProgramiv(m_program, GL_LINK_STATUS, &ok);
	if (!ok) throw std::runtime_error("viewer shaders do not link");
	m_uViewProj = glGetUniformLocation(m_program, "uViewProj");
	m_uModel = glGetUniformLocation(m_program, "uModel");
	m_uScale = glGetUniformLocation(m_program, "uScale");
	m_uColour = glGetUniformLocation(m_program, "uColour");
	m_uMode = glGetUniformLocation(m_program, "uMode");
	m_uEdges = glGetUniformLocation(m_program, "uEdges");
	m_uAlpha = glGetUniformLocation(m_program, "uAlpha");

	std::vector<float> vertices;
	std::vector<unsigned> indices;
	cubeMesh(vertices, indices);
	glGenVertexArrays(1, &m_cubeVao);
	glBindVertexArray(m_cubeVao);
	glGenBuffers(1, &m_cubeVbo);
	glBindBuffer(GL_ARRAY_BUFFER, m_cubeVbo);
	glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
	glGenBuffers(1, &m_cubeEbo);
	glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_cubeEbo);
	glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(unsigned)), indices.data(), GL_STATIC_DRAW);
	setVertexLayout();

	glGenVertexArrays(1, &m_dynamicVao);
	glBindVertexArray(m_dynamicVao);
	glGenBuffers(1, &m_dynamicVbo);
	glBindBuffer(GL_ARRAY_BUFFER, m_dynamicVbo);
	setVertexLayout();
	glBindVertexArray(0);
}

Renderer::~Renderer()
{
	glDeleteBuffers(1, &m_cubeVbo);
	glDeleteBuffers(1, &m_cubeEbo);
	glDeleteBuffers(1, &m_dynamicVbo);
	glDeleteVertexArrays(1, &m_cubeVao);
	glDeleteVertexArrays(1, &m_dynamicVao);
	glDeleteProgram(m_program);
}

void Renderer::drawTrial(harness::Trial& trial, const OrbitCamera& camera, const Viewport& viewport, const DrawOptions& options)
{
	glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
	glScissor(viewport.x, viewport.y, viewport.width, viewport.height);
	glEnable(GL_SCISSOR_TEST);
	const Rgb sky = backgroundColour();
	glClearColor(sky.r, sky.g, sky.b, 1);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	glEnable(GL_DEPTH_TEST);
	glEnable(GL_CULL_FACE);
	glDisable(GL_BLEND);
	glUseProgram(m_program);
	const Mat4 viewProj = camera.projection(viewport.aspect()) * camera.view();
	glUniformMatrix4fv(m_uViewProj, 1, GL_FALSE, viewProj.m);
	glUniform1f(m_uAlpha, 1);

	const auto colours = bodyColours(trial, options.colours);
	const btCollisionObject* ground = trial.scene().ground();
	const btCollisionObjectArray& objects = trial.simulation().world().getCollisionObjectArray();
	for (int i = 0; i < objects.size(); ++i)
	{
		const btCollisionObject& object = *objects[i];
		if (&object == ground)
		{
			drawBody(object, groundColour(), kModeGround);
		}
		else if (!object.isStaticOrKinematicObject())
		{
			const auto found = colours.find(&object);
			drawBody(object, found != colours.end() ? found->second : layerlessColour(), kModeBody);
		}
	}
	// Static bodies other than the ground (pit walls, ramps, posts) last and translucent, so they
	// never hide what moves.
	glEnable(GL_BLEND);
	glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
	glDepthMask(GL_FALSE);
	glUniform1f(m_uAlpha, kStaticAlpha);
	for (int i = 0; i < objects.size(); ++i)
	{
		const btCollisionObject& object = *objects[i];
		if (&object != ground && object.isStaticOrKinematicObject()) drawBody(object, staticColour(), kModeBody);
	}
	glUniform1f(m_uAlpha, 1);
	glDepthMask(GL_TRUE);
	glDisable(GL_BLEND);
	if (options.contacts) drawContacts(trial, options);
	glBindVertexArray(0);
	glUseProgram(0);
	glDisable(GL_SCISSOR_TEST);
}

void Renderer::drawBody(const btCollisionObject& object, const Rgb& colour, int mode)
{
	const btCollisionShape* shape = object.getCollisionShape();
	const btTransform& xf = object.getWorldTransform();
	if (!(xf.getOrigin().length2() < btScalar(1e12))) return;  // NaN, Inf or far away: nothing to see
	const Mat4 model = toMat4(xf);
	glUniformMatrix4fv(m_uModel, 1, GL_FALSE, model.m);
	glUniform3f(m_uColour, colour.r, colour.g, colour.b);
	glUniform1i(m_uMode, mode);
	if (shape->getShapeType() == BOX_SHAPE_PROXYTYPE)
	{
		const btVector3 half = static_cast<const btBoxShape*>(shape)->getHalfExtentsWithMargin();
		glUniform3f(m_uScale, float(half.x()), float(half.y()), float(half.z()));
		glUniform1i(m_uEdges, mode == kModeBody ? 1 : 0);
		glBindVertexArray(m_cubeVao);
		glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, nullptr);
		return;
	}
	if (!shape->isConvex()) return;  // the registry has boxes and convex hulls only
	const std::vector<float> mesh = hullMesh(*static_cast<const btConvexShape*>(shape));
	glUniform3f(m_uScale, 1, 1, 1);
	glUniform1i(m_uEdges, 0);
	glBindVertexArray(m_dynamicVao);
	glBindBuffer(GL_ARRAY_BUFFER, m_dynamicVbo);
	glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.size() * sizeof(float)), mesh.data(), GL_STREAM_DRAW);
	glDrawArrays(GL_TRIANGLES, 0, GLsizei(mesh.size() / 6));
}

void Renderer::drawContacts(harness::Trial& trial, const DrawOptions& options)
{
	double weight = 0;
	for (const btRigidBody* b : trial.bodies()) weight += trial.simulation().gravity() / double(b->getInvMass());
	const double metresPerNewton = weight > 0 ? options.forceScale * double(trial.bodies().size()) / weight : 0.0;
	const double dt = trial.simulation().timeStep();
	std::vector<float> points, lines;
	btDispatcher& dispatcher = *trial.simulation().world().getDispatcher();
	for (int i = 0; i < dispatcher.getNumManifolds(); ++i)
	{
		const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
		for (int j = 0; j < m->getNumContacts(); ++j)
		{
			const btManifoldPoint& cp = m->getContactPoint(j);
			if (cp.getDistance() > m->getContactProcessingThreshold() && cp.getDistance() > btScalar(0.02)) continue;
			const btVector3 p = cp.getPositionWorldOnB();
			// m_normalWorldOnB points from B to A; draw the push on whichever body is above.
			const btVector3 up = cp.m_normalWorldOnB.y() >= 0 ? cp.m_normalWorldOnB : -cp.m_normalWorldOnB;
			const btVector3 q = p + up * btScalar(double(cp.m_appliedImpulse) / dt * metresPerNewton);
			points.insert(points.end(), {float(p.x()), float(p.y()), float(p.z()), 0, 0, 0});
			lines.insert(lines.end(), {float(p.x()), float(p.y()), float(p.z()), 0, 0, 0, float(q.x()), float(q.y()), float(q.z()), 0, 0, 0});
		}
	}
	// On top of the bodies: contacts inside a stack are hidden by the bodies otherwise.
	glDisable(GL_DEPTH_TEST);
	const Mat4 identity = Mat4::identity();
	glUniformMatrix4fv(m_uModel, 1, GL_FALSE, identity.m);
	glUniform3f(m_uScale, 1, 1, 1);
	glUniform1i(m_uMode, kModeUnlit);
	glUniform1i(m_uEdges, 0);
	drawLines(lines, {0.95f, 0.1f, 0.1f}, GL_LINES);
	glPointSize(4);
	drawLines(points, {0.1f, 0.1f, 0.1f}, GL_POINTS);
	glEnable(GL_DEPTH_TEST);
}

void Renderer::drawLines(const std::vector<float>& xyz, const Rgb& colour, unsigned primitive)
{
	if (xyz.empty()) return;
	glUniform3f(m_uColour, colour.r, colour.g, colour.b);
	glBindVertexArray(m_dynamicVao);
	glBindBuffer(GL_ARRAY_BUFFER, m_dynamicVbo);
	glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(xyz.size() * sizeof(float)), xyz.data(), GL_STREAM_DRAW);
	glDrawArrays(primitive, 0, GLsizei(xyz.size() / 6));
}
}  // namespace viewer
