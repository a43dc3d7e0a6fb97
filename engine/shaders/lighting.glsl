// Blinn-Phong with per-light falloff. Directions point from the surface towards the light.
#include "frame.glsl"

// Unit vector towards light `i` and its distance/cone attenuation (1 for directional lights).
void gsLightIncidence(int i, vec3 worldPosition, out vec3 toLight, out float attenuation) {
    GsLight light = gsLights[i];
    toLight = -light.direction.xyz;
    attenuation = 1.0;
#ifdef GS_HAS_POSITIONAL_LIGHTS
    int type = int(light.position.w);
    if (type != GS_LIGHT_DIRECTIONAL) {
        vec3 offset = light.position.xyz - worldPosition;
        float distanceToLight = length(offset);
        toLight = distanceToLight > 0.0 ? offset / distanceToLight : -light.direction.xyz;
        float cone = 1.0;
        if (type == GS_LIGHT_SPOT) {
            float cosAngle = dot(-toLight, light.direction.xyz);
            // smoothstep needs edge0 < edge1: guard a zero-width cone.
            cone = light.spot.x > light.spot.y ? smoothstep(light.spot.y, light.spot.x, cosAngle)
                                               : step(light.spot.y, cosAngle);
        }
        // KHR_lights_punctual, "Range Property": the inverse square windowed by clamp(1 - (d/range)^4, 0, 1),
        // which reaches zero at the range smoothly; range 0 means unlimited (plain inverse square).
        float window = 1.0;
        if (light.spot.z > 0.0) {
            float ratio = distanceToLight / light.spot.z;
            window = clamp(1.0 - (ratio * ratio) * (ratio * ratio), 0.0, 1.0);
        }
        // Inverse-square falloff, clamped so a surface at the light's position stays finite.
        attenuation = cone * window / max(distanceToLight * distanceToLight, 1e-4);
    }
#endif
}

vec3 gsBlinnPhong(vec3 normal, vec3 toLight, vec3 toCamera, vec3 lightColor, vec3 baseColor, vec3 specularColor,
                  float shininess) {
    float lambert = max(dot(normal, toLight), 0.0);
    vec3 halfway = normalize(toLight + toCamera);
    float specular = lambert > 0.0 ? pow(max(dot(normal, halfway), 0.0), shininess) : 0.0;
    return lightColor * (baseColor * lambert + specularColor * specular);
}
