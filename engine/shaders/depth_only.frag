#version 450 core
// Depth pre-pass: depth only; the lighting pass then shades each visible pixel once (EQUAL depth test).
void main() {}
