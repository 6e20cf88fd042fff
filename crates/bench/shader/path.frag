#version 330 core
// Chapter 6 as a fragment shader: the lab model's "the same scene, physically"
// with lab materials, a point sun and no caustics, `spp` random paths per
// pixel. It follows chapters/06-path-tracing/src/integrator.rs step by step
// (the same estimator, so the same expected image and the same variance)
// with its own random numbers, so the two agree in the mean, not in bytes.

#include "lab.glsl"

uniform int spp;       // paths per pixel
uniform uint seed;     // varies the random numbers from one run to the next
uniform int max_depth; // the most surface hits on a path (chapter 6: 10)
// The sun's irradiance on a surface facing it: 0.1 · E (the lab model).
const float E_SUN = 2.5;
const float FRAC_1_PI = 0.318309886;

// rgb: the pixel's mean radiance (linear); a: rays traced, counted as
// chapter 6 counts them: every segment of every path, and every shadow ray.
layout(location = 0) out vec4 out_radiance;
// rgb: the variance of that mean, estimated from the pixel's own paths.
layout(location = 1) out vec4 out_variance;

// --------------------------------------------------------- random numbers

// A PCG generator per pixel (O'Neill's RXS-M-XS output on a 32-bit LCG, the
// "PCG hash" of Jarzynski and Olano, JCGT 2020): cheap, with no tables,
// and good enough that a pixel's paths are independent.
uint rng_state;

uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Uniform in [0, 1): the top 24 bits, every one a float exactly.
float uniform01() {
    rng_state = rng_state * 747796405u + 2891336453u;
    uint word = ((rng_state >> ((rng_state >> 28u) + 4u)) ^ rng_state) * 277803737u;
    word = (word >> 22u) ^ word;
    return float(word >> 8u) * (1.0 / 16777216.0);
}

// ------------------------------------------------------------- sampling

// Two unit vectors that make an orthonormal frame with the unit n (Duff et
// al., JCGT 2017; glam's any_orthonormal_pair, which the Rust uses).
void orthonormal_pair(vec3 n, out vec3 t, out vec3 b) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

// A direction around n with density cos θ / π (Malley's method): a uniform
// point on the unit disc, lifted onto the hemisphere. The Rust finds the
// point by rejection from the square around it; a shader had better not:
// the lanes that must try again hold the other seven up. And on this
// llvmpipe (Mesa 22.3.6) an unbounded rejection loop gave wrong points,
// E[r²] = 0.558 instead of 0.5, which `run.py --check` caught as a ground
// 2 % too bright (rejection_loop.py shows it). So: polar coordinates, one
// try, every lane in step.
vec3 cosine_direction(vec3 n) {
    float r = sqrt(uniform01());
    float phi = 6.28318530718 * uniform01();
    float x = r * cos(phi);
    float y = r * sin(phi);
    vec3 t, b;
    orthonormal_pair(n, t, b);
    return x * t + y * b + sqrt(max(1.0 - r * r, 0.0)) * n;
}

// ----------------------------------------------------------------- paths

int rays; // traced by this fragment so far

// One random path from the eye: its radiance.
vec3 trace(Ray ray) {
    vec3 radiance = vec3(0.0);
    // The share of the light found further along that reaches the eye: a
    // colour, since every diffuse bounce tints it by an albedo.
    vec3 throughput = vec3(1.0);
    vec3 l = to_sun();
    for (int hits = 1; hits <= max_depth + 1; hits++) {
        rays++;
        Hit hit;
        if (hits > max_depth) {
            // One segment more than the depth allows: only whether it
            // escapes to the sky matters.
            if (any_hit(ray)) break;
            radiance += throughput * sky(ray.direction);
            break;
        }
        if (!nearest_hit(ray, hit)) {
            // Escaped: the sky's light. The sun is a point (a delta light):
            // no path can hit it, only the shadow rays below find it.
            radiance += throughput * sky(ray.direction);
            break;
        }
        float r = hit.material.reflection;
        float t = hit.material.transmission;
        // Choose the lobe with the probability of its share, so the share
        // cancels from the estimate: the mirror in [0, r), the refraction in
        // [r, r + t), the diffuse above. A matte surface draws nothing.
        float u = r + t > 0.0 ? uniform01() : 1.0;
        vec3 d = ray.direction;
        vec3 nf = hit.facing_normal;
        if (u >= r + t) {
            // Diffuse. The sun by next-event estimation: a shadow ray, and
            // albedo/π · E_sun · cos θ if nothing is in the way.
            vec3 albedo = hit.material.albedo;
            float cos_theta = dot(nf, l);
            if (cos_theta > 0.0) {
                rays++;
                if (!any_hit(Ray(hit.point + l * EPSILON, l))) {
                    radiance += throughput * (albedo * FRAC_1_PI * E_SUN * cos_theta);
                }
            }
            // Everything else, the sky and the other surfaces: one new
            // direction in proportion to cos θ, whose estimate
            // f·cos/pdf = (albedo/π)·cos/(cos/π) is the albedo.
            throughput *= albedo;
            ray = Ray(hit.point + nf * EPSILON, cosine_direction(nf));
            continue;
        }
        vec3 next;
        if (u < r) {
            next = mirror(d, nf);
        } else {
            next = refract(d, nf, eta_of(hit));
            // Total internal reflection: the light goes along the mirror.
            if (next == vec3(0.0)) next = mirror(d, nf);
        }
        next = normalize(next);
        ray = Ray(hit.point + next * EPSILON, next);
    }
    return radiance;
}

void main() {
    // Row 0 at the top, as the image is written.
    vec2 pixel = vec2(floor(gl_FragCoord.x), resolution.y - 1.0 - floor(gl_FragCoord.y));
    // Seeded by (seed, pixel): the same image whatever order the tiles run in.
    uint index = uint(pixel.y) * uint(resolution.x) + uint(pixel.x);
    rng_state = pcg_hash(index ^ pcg_hash(seed));

    rays = 0;
    vec3 sum = vec3(0.0);
    vec3 sum_sq = vec3(0.0);
    for (int s = 0; s < spp; s++) {
        // Uniformly random over the pixel: it converges to the pixel's
        // average radiance (a box filter), as chapter 6's does.
        vec2 offset = vec2(uniform01(), uniform01());
        vec3 x = trace(camera_ray(pixel, offset));
        sum += x;
        sum_sq += x * x;
    }
    float n = float(spp);
    vec3 mean = sum / n;
    vec3 variance = n > 1.0 ? max((sum_sq - n * mean * mean) / (n - 1.0), 0.0) / n : vec3(0.0);
    out_radiance = vec4(mean, float(rays));
    out_variance = vec4(variance, 0.0);
}
