// The lab scene of the lab model (the book's appendix) in GLSL: camera, ground, five
// spheres, sky and sun, and the two hit queries. Shared by whitted.frag and
// path.frag, which include it by name; GLSL has no include of its own, so
// moderngl pastes it in (run.py registers it in `ctx.includes`).
//
// Everything is 32-bit float, as in the lab model and in the Rust. The order of
// the arithmetic follows src/ (sphere.rs, plane.rs, scene.rs, camera.rs), so
// that the two differ only where the JIT fuses a multiply and an add.

uniform vec2 resolution; // the image's width and height in pixels

// ---------------------------------------------------------------- camera

const vec3 EYE = vec3(0.0, 1.2, 4.5);
const vec3 TARGET = vec3(0.0, 0.6, 0.0);
const vec3 UP = vec3(0.0, 1.0, 0.0);
// tan(22.5°) rounded to f32, as the lab model gives it: no tan() in the shader,
// whose precision GLSL leaves to the implementation.
const float HALF_HEIGHT = 0.41421357;

struct Ray {
    vec3 origin;
    vec3 direction; // always of unit length
};

// The ray through the point `offset` in [0,1]² of pixel (i, j), row 0 at the
// top. A fragment's gl_FragCoord counts rows from the bottom, so the caller
// turns it round.
Ray camera_ray(vec2 pixel, vec2 offset) {
    vec3 f = normalize(TARGET - EYE);
    vec3 r = normalize(cross(f, UP));
    vec3 u = cross(r, f);
    float aspect = resolution.x / resolution.y;
    float x = (2.0 * (pixel.x + offset.x) / resolution.x - 1.0) * HALF_HEIGHT * aspect;
    float y = (1.0 - 2.0 * (pixel.y + offset.y) / resolution.y) * HALF_HEIGHT;
    return Ray(EYE, normalize(f + x * r + y * u));
}

// ----------------------------------------------------------------- scene

struct Material {
    vec3 albedo;
    float reflection;   // r: the share sent on as a mirror ray
    float transmission; // t: the share sent on through the glass
    float ior;
};

const int SPHERES = 5;
// Centre (xyz) and radius (w), in the lab model's table order: mirror, glass, red,
// blue, yellow. The order matters: on a tie the earlier object wins.
const vec4 SPHERE[SPHERES] = vec4[](
    vec4(-1.25, 0.5, 0.5, 0.5),
    vec4(1.0, 0.6, 0.8, 0.6),
    vec4(0.0, 1.0, -1.5, 1.0),
    vec4(0.1, 0.25, 1.2, 0.25),
    vec4(-2.0, 0.75, -1.2, 0.75)
);
const Material SPHERE_MATERIAL[SPHERES] = Material[](
    Material(vec3(0.5, 0.2, 0.6), 0.6, 0.0, 1.0),
    Material(vec3(0.2, 0.7, 0.3), 0.1, 0.7, 1.5),
    Material(vec3(0.8, 0.2, 0.15), 0.0, 0.0, 1.0),
    Material(vec3(0.15, 0.3, 0.85), 0.0, 0.0, 1.0),
    Material(vec3(0.9, 0.75, 0.2), 0.0, 0.0, 1.0)
);

const vec3 HORIZON = vec3(0.85, 0.90, 1.00);
const vec3 ZENITH = vec3(0.25, 0.45, 0.85);

// Towards the sun, normalised in the shader as the Rust normalises it.
vec3 to_sun() {
    return normalize(vec3(-1.0, 1.2, 0.8));
}

// The sky seen along the unit direction d: the square root widens the
// bright band near the horizon.
vec3 sky(vec3 d) {
    float t = sqrt(clamp(d.y, 0.0, 1.0));
    return (1.0 - t) * HORIZON + t * ZENITH;
}

// The checkerboard of unit squares: floor, not int(), since truncation
// would merge the squares either side of x = 0 into a double-width stripe.
vec3 ground_albedo(vec3 p) {
    float s = floor(p.x) + floor(p.z);
    return (int(s) & 1) == 0 ? vec3(0.75) : vec3(0.25);
}

// ---------------------------------------------------------- intersection

const float NO_HIT = -1.0;

// The ground: the plane through the origin with normal +y.
float hit_ground(Ray ray) {
    const vec3 n = vec3(0.0, 1.0, 0.0);
    float dn = dot(ray.direction, n);
    if (abs(dn) < 1e-8) return NO_HIT; // parallel to the plane
    float t = dot(vec3(0.0) - ray.origin, n) / dn;
    return t > 0.0 ? t : NO_HIT;
}

// The ray–sphere quadratic, the nearer root that lies ahead of the origin.
float hit_sphere(Ray ray, vec4 sphere) {
    vec3 oc = ray.origin - sphere.xyz;
    float b = dot(oc, ray.direction);
    float q = dot(oc, oc) - sphere.w * sphere.w;
    float disc = b * b - q;
    if (disc < 0.0) return NO_HIT; // the line misses the sphere
    float root = sqrt(disc);
    float t0 = -b - root; // where the ray enters
    if (t0 > 0.0) return t0;
    float t1 = -b + root; // where it leaves: the origin is inside
    return t1 > 0.0 ? t1 : NO_HIT;
}

struct Hit {
    vec3 point;
    vec3 normal;        // outward, unit
    vec3 facing_normal; // towards the side the ray came from
    bool entering;
    Material material;
    int object; // -1 the ground, 0.. the spheres
};

// The nearest surface along the ray. Only a strictly nearer hit replaces
// the best so far, so ties go to the earlier object (the ground first).
bool nearest_hit(Ray ray, out Hit hit) {
    float nearest = uintBitsToFloat(0x7F800000u); // +infinity
    int object = -2;           // nothing yet
    float t = hit_ground(ray);
    if (t > 0.0) {
        nearest = t;
        object = -1;
    }
    for (int i = 0; i < SPHERES; i++) {
        t = hit_sphere(ray, SPHERE[i]);
        if (t > 0.0 && t < nearest) {
            nearest = t;
            object = i;
        }
    }
    if (object == -2) return false;

    hit.object = object;
    hit.point = ray.origin + ray.direction * nearest;
    if (object == -1) {
        hit.normal = vec3(0.0, 1.0, 0.0);
        hit.material = Material(ground_albedo(hit.point), 0.0, 0.0, 1.0);
    } else {
        hit.normal = normalize(hit.point - SPHERE[object].xyz);
        hit.material = SPHERE_MATERIAL[object];
    }
    hit.entering = dot(ray.direction, hit.normal) < 0.0;
    hit.facing_normal = hit.entering ? hit.normal : -hit.normal;
    return true;
}

// Whether anything at all is in the way: the shadow-ray query, which may
// stop at the first hit it finds.
bool any_hit(Ray ray) {
    if (hit_ground(ray) > 0.0) return true;
    for (int i = 0; i < SPHERES; i++) {
        if (hit_sphere(ray, SPHERE[i]) > 0.0) return true;
    }
    return false;
}

// The mirror direction, as the lab model writes it (GLSL's own reflect() is the
// same formula; spelled out so that a reader sees it).
vec3 mirror(vec3 d, vec3 n) {
    return d - 2.0 * dot(d, n) * n;
}

// n₁/n₂ across the surface: 1/ior going in, ior coming out.
float eta_of(Hit hit) {
    return hit.entering ? 1.0 / hit.material.ior : hit.material.ior;
}

// Where a secondary ray starts: a little off the surface along its own
// direction, so that it does not hit the point it leaves.
const float EPSILON = 1e-4;
