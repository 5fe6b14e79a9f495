#version 460
// gi.prt: the nearest surface's interpolated irradiance, kept finite in the half-float target
// (NaN to 0, at most 65504 in magnitude), and its coverage (the share of valid vertices).
layout(location = 0) in vec4 irradiance;
layout(location = 0) out vec4 out_irradiance;

void main() {
  vec3 e = mix(irradiance.rgb, vec3(0.0), isnan(irradiance.rgb));
  out_irradiance = vec4(clamp(e, vec3(-65504.0), vec3(65504.0)), clamp(irradiance.a, 0.0, 1.0));
}
