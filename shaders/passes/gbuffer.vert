#version 450
// G-buffer pass: meshes are in world space already (transforms are applied at load).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aTangent;
uniform mat4 uViewProjection;
out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;
out vec4 vTangent;
// Techniques' forward passes draw their objects again over this depth with LEQUAL
// (techniques/technique_pass.h): the same expression, invariant, gives the same depth.
invariant gl_Position;

void main() {
  vPosition = aPosition;
  vNormal = aNormal;
  vUv = aUv;
  vTangent = aTangent;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
