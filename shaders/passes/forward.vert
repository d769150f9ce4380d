#version 450
// Forward pass: small meshes drawn after deferred lighting (light gizmos), placed by a model
// matrix, depth-tested against the G-buffer's depth.
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
uniform mat4 uModel;

void main() { gl_Position = uViewProjection * uModel * vec4(aPosition, 1.0); }
