#version 450
// Loader fixture: compiles, but a compute program without main() cannot link.
layout(local_size_x = 1) in;
float unused() { return 1.0; }
