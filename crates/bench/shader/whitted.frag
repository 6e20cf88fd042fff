#version 330 core
// Chapter 5 of the lab as the 2016 lab ran it: a fragment shader, one
// fragment per pixel, each tracing its five rays through a fixed-size ray
// stack (GLSL has no recursion and no heap). The model is the lab's, to the
// formula; the Rust it is checked against is chapters/01..05 and src/.
//
// A GPU (or Mesa's llvmpipe, which compiles this for the CPU's 8-wide AVX
// registers) runs neighbouring fragments in lockstep, one lane each. When 3
// lanes of 8 hit the glass and 5 the ground, all 8 walk through both paths
// of every branch below, with the lanes that did not take it masked off:
// that divergence is what chapter 7's wave loop avoids by packing rays.

#include "lab.glsl"

// The lab model's chapter 5: shadows, reflection and transmission on, depth 10.
const int MAX_DEPTH = 10;
// Each hit pushes at most two rays, and the reflected ray waits while the
// transmitted subtree is traced, so at most one ray per level waits: the
// stack never holds more than MAX_DEPTH + 1 rays.
const int STACK_SIZE = MAX_DEPTH + 1;

const float E = 25.0;        // the sun's brightness
const float SUN_LIT = 0.1;   // k when the shadow ray escapes
const float SUN_IN_SHADOW = 0.01; // k when it hits anything
const float AMBIENT = 0.04;
const float PI = 3.14159265358979;

// rgb: the pixel encoded as the lab model says, as level / 255 (exact in an 8-bit
// target); a: how many rays the fragment traced, every kind counted, as
// the Rust counts them (primary, reflected, refracted, shadow).
layout(location = 0) out vec4 out_colour;

// The lab's five rays per pixel: the centre, then the middle of each
// quarter, top left, top right, bottom left, bottom right.
const vec2 LAB_FIVE[5] = vec2[](
    vec2(0.5, 0.5), vec2(0.25, 0.25), vec2(0.75, 0.25), vec2(0.25, 0.75), vec2(0.75, 0.75)
);

// The ray stack: parallel arrays, as a shader has to hold it.
vec3 stack_origin[STACK_SIZE];
vec3 stack_direction[STACK_SIZE];
float stack_weight[STACK_SIZE];
int stack_depth[STACK_SIZE];
int stack_len;

void push(vec3 origin, vec3 direction, float weight, int depth) {
    stack_origin[stack_len] = origin;
    stack_direction[stack_len] = direction;
    stack_weight[stack_len] = weight;
    stack_depth[stack_len] = depth;
    stack_len++;
}

int rays; // traced by this fragment so far

// Lambert under the sun, plus the ambient term; k says whether the shadow
// ray found the sun. albedo/π first, then the irradiance, as the Rust does.
vec3 local_light(Hit hit) {
    vec3 l = to_sun();
    rays++; // the shadow ray
    bool shadowed = any_hit(Ray(hit.point + l * EPSILON, l));
    float k = shadowed ? SUN_IN_SHADOW : SUN_LIT;
    float cos_theta = max(0.0, dot(hit.facing_normal, l));
    float irradiance = k * E * cos_theta;
    vec3 albedo = hit.material.albedo;
    return albedo / PI * irradiance + albedo * AMBIENT;
}

// ANCHOR: trace
// One camera ray's colour: the lab model's ray-stack loop.
vec3 trace(Ray primary) {
    vec3 colour = vec3(0.0);
    stack_len = 0;
    push(primary.origin, primary.direction, 1.0, 1);
    while (stack_len > 0) {
        stack_len--;
        Ray ray = Ray(stack_origin[stack_len], stack_direction[stack_len]);
        float w = stack_weight[stack_len];
        int depth = stack_depth[stack_len];
        rays++;

        Hit hit;
        if (!nearest_hit(ray, hit)) {
            colour += w * sky(ray.direction);
            continue;
        }
        float r = hit.material.reflection;
        float t = hit.material.transmission;
        // The share kept for local shading: 1 - r - t, subtracted one share
        // at a time as the lab model writes it (and as the Rust does).
        float kept = 1.0 - r - t;
        colour += w * kept * local_light(hit);

        if (depth < MAX_DEPTH) {
            vec3 R = normalize(mirror(ray.direction, hit.facing_normal));
            // The reflected ray goes on the stack first, so the transmitted
            // subtree is popped (traced) first.
            if (r > 0.0) push(hit.point + R * EPSILON, R, w * r, depth + 1);
            if (t > 0.0) {
                vec3 T = refract(ray.direction, hit.facing_normal, eta_of(hit));
                if (T == vec3(0.0)) {
                    // Total internal reflection: the lab pushed a zero
                    // direction here; the lab model sends the energy along R.
                    push(hit.point + R * EPSILON, R, w * t, depth + 1);
                } else {
                    T = normalize(T);
                    push(hit.point + T * EPSILON, T, w * t, depth + 1);
                }
            }
        }
    }
    return colour;
}
// ANCHOR_END: trace

// The lab model's encoding of one linear channel: clamp, the sRGB curve, and the
// nearest of 256 levels with halves rounded up (GLSL's round() may go
// either way on a half; floor(v + 0.5) does not).
float encode(float c) {
    c = clamp(c, 0.0, 1.0);
    float v = c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
    return floor(255.0 * v + 0.5) / 255.0;
}

void main() {
    // Row 0 at the top, as the image is written.
    vec2 pixel = vec2(floor(gl_FragCoord.x), resolution.y - 1.0 - floor(gl_FragCoord.y));
    rays = 0;
    vec3 sum = vec3(0.0);
    for (int s = 0; s < 5; s++) {
        sum += trace(camera_ray(pixel, LAB_FIVE[s]));
    }
    vec3 colour = sum / 5.0;
    out_colour = vec4(encode(colour.r), encode(colour.g), encode(colour.b), float(rays));
}
