#version 450
// Shadow pass: the depth test writes the map; nothing to shade.
void main() {}
