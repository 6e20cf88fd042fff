// Chapter 10: the lab's tracer as a WGSL compute shader.
//
// One invocation per pixel: each one traces its pixel's rays with the lab model's
// camera, shapes, shading and ray stack, exactly as chapters 1-5 do in
// Rust, and writes the pixel's colour in linear light. The program
// (`ch10-gpu`) builds the inputs from the core's `raylab::Scene`, reads
// the colours back and encodes them with the core's sRGB encoder.
//
// Edit this file and run `cargo run -p ch10-gpu -- --watch`: the program
// renders again on every save. A mistake prints naga's message with its
// line and column, and the last good shader stays in use.
//
// `cargo run -p learn -- start shader` hands this file out with the lab's
// three tasks blanked (the `todo_` regions in `trace_ray`: the shadow
// feeler, the reflection push, the refraction push), and `check shader`
// judges them by chapters 2-4's pictures.

// ANCHOR: inputs
// What every invocation reads: the camera, the light, the ground, the
// limits of the ray tree, and which of chapters 1-5 to be (`features`).
struct Params {
    eye: vec3<f32>,
    width: u32,
    forward: vec3<f32>,
    height: u32,
    right: vec3<f32>,
    half_height: f32,
    up: vec3<f32>,
    epsilon: f32,
    to_sun: vec3<f32>,
    sun_brightness: f32,
    horizon: vec3<f32>,
    max_depth: u32,
    zenith: vec3<f32>,
    spp: u32,
    ground_point: vec3<f32>,
    sphere_count: u32,
    ground_normal: vec3<f32>,
    // Bit 0: shadow feelers (chapter 2 on); bit 1: reflection (chapter 3
    // on); bit 2: transmission (chapter 4 on).
    features: u32,
    even: vec3<f32>,
    // The image goes to the GPU in bands of rows when it is too big for
    // one buffer: this band's first row and its number of rows.
    first_row: u32,
    odd: vec3<f32>,
    band_rows: u32,
    // The most rays an invocation traces in one dispatch (see `main`).
    steps: u32,
}

// A sphere and its material, as the storage buffer holds them (48 bytes).
struct Sphere {
    centre: vec3<f32>,
    radius: f32,
    albedo: vec3<f32>,
    reflection: f32,
    transmission: f32,
    ior: f32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> spheres: array<Sphere>;
// Where a pixel's rays cross it, the same offsets for every pixel:
// the centre, or the lab's five, or a grid.
@group(0) @binding(2) var<storage, read> samples: array<vec2<f32>>;
// Out: each pixel's colour in linear light (the fourth number is unused).
@group(0) @binding(3) var<storage, read_write> pixels: array<vec4<f32>>;
// Out: each pixel's deepest ray and its number of rays, for the heat maps.
@group(0) @binding(4) var<storage, read_write> maps: array<vec2<u32>>;
// Out: per image row, the rays traced of each kind and the samples cut
// short by the ray budget. Thousands of invocations add to these at
// once, so they are atomic; one counter per row keeps them from all
// queuing on the same six.
@group(0) @binding(5) var<storage, read_write> counts: array<atomic<u32>>;
// Between dispatches: each pixel's progress and the rays on its stack,
// and how many pixels are not done yet (see `main`).
@group(0) @binding(6) var<storage, read_write> progress: array<Progress>;
@group(0) @binding(7) var<storage, read_write> stacks: array<array<Pending, STACK_SIZE>>;
@group(0) @binding(8) var<storage, read_write> unfinished: atomic<u32>;
// ANCHOR_END: inputs

const SHADOWS: u32 = 1u;
const REFLECTION: u32 = 2u;
const TRANSMISSION: u32 = 4u;

// The ray kinds, in the order of the core's `RayKind::ALL`.
const PRIMARY: u32 = 0u;
const SHADOW: u32 = 1u;
const REFLECTED: u32 = 2u;
const REFRACTED: u32 = 3u;
const TOTAL_INTERNAL: u32 = 4u;
const KINDS: u32 = 5u;
// Six counters per row: the five kinds, then the samples over budget.
const COUNTERS_PER_ROW: u32 = 6u;

// ANCHOR: constants
const PI: f32 = 3.14159265358979;
const SUN_LIT: f32 = 0.1;
const SUN_IN_SHADOW: f32 = 0.01;
const AMBIENT: f32 = 0.04;
// ANCHOR_END: constants

// ANCHOR: camera
// The ray through the point `offset` of pixel (i, j), row 0 at the top.
fn camera_ray(i: u32, j: u32, offset: vec2<f32>) -> vec3<f32> {
    let w = f32(params.width);
    let h = f32(params.height);
    let aspect = w / h;
    let x = (2.0 * (f32(i) + offset.x) / w - 1.0) * params.half_height * aspect;
    let y = (1.0 - 2.0 * (f32(j) + offset.y) / h) * params.half_height;
    return normalize(params.forward + x * params.right + y * params.up);
}
// ANCHOR_END: camera

// ANCHOR: intersect
// No `Option` in WGSL: a distance of -1 means "no hit".
const MISS: f32 = -1.0;

fn intersect_sphere(origin: vec3<f32>, direction: vec3<f32>, sphere: Sphere) -> f32 {
    let oc = origin - sphere.centre;
    let b = dot(oc, direction);
    let q = dot(oc, oc) - sphere.radius * sphere.radius;
    let disc = b * b - q;
    if disc < 0.0 {
        return MISS;
    }
    let root = sqrt(disc);
    let t0 = -b - root;
    if t0 > 0.0 {
        return t0;
    }
    let t1 = -b + root;
    if t1 > 0.0 {
        return t1;
    }
    return MISS;
}

fn intersect_ground(origin: vec3<f32>, direction: vec3<f32>) -> f32 {
    let denom = dot(direction, params.ground_normal);
    if abs(denom) < 1e-8 {
        return MISS;
    }
    let t = dot(params.ground_point - origin, params.ground_normal) / denom;
    if t > 0.0 {
        return t;
    }
    return MISS;
}
// ANCHOR_END: intersect

// ANCHOR: nearest_hit
// What a ray meets, as the core's `Hit`: `object` is -1 for the ground,
// the sphere's index otherwise; `found` is false for the sky.
struct Hit {
    found: bool,
    object: i32,
    t: f32,
    point: vec3<f32>,
    normal: vec3<f32>,
    facing_normal: vec3<f32>,
    entering: bool,
    albedo: vec3<f32>,
    reflection: f32,
    transmission: f32,
    ior: f32,
}

// The ground, then the spheres in order; only a strictly nearer hit
// replaces the best so far, so ties go to the earlier object.
fn nearest_hit(origin: vec3<f32>, direction: vec3<f32>) -> Hit {
    var hit: Hit;
    hit.found = false;
    let ground = intersect_ground(origin, direction);
    if ground > 0.0 {
        hit.found = true;
        hit.object = -1;
        hit.t = ground;
    }
    for (var i = 0u; i < params.sphere_count; i++) {
        let t = intersect_sphere(origin, direction, spheres[i]);
        if t > 0.0 && (!hit.found || t < hit.t) {
            hit.found = true;
            hit.object = i32(i);
            hit.t = t;
        }
    }
    if !hit.found {
        return hit;
    }
    hit.point = origin + hit.t * direction;
    if hit.object < 0 {
        hit.normal = params.ground_normal;
        hit.albedo = checker(hit.point);
        hit.reflection = 0.0;
        hit.transmission = 0.0;
        hit.ior = 1.0;
    } else {
        let sphere = spheres[hit.object];
        hit.normal = normalize(hit.point - sphere.centre);
        hit.albedo = sphere.albedo;
        hit.reflection = sphere.reflection;
        hit.transmission = sphere.transmission;
        hit.ior = sphere.ior;
    }
    hit.entering = dot(direction, hit.normal) < 0.0;
    hit.facing_normal = select(-hit.normal, hit.normal, hit.entering);
    return hit;
}

// The shadow feeler's question: is anything at all in the way?
fn any_hit(origin: vec3<f32>, direction: vec3<f32>) -> bool {
    if intersect_ground(origin, direction) > 0.0 {
        return true;
    }
    for (var i = 0u; i < params.sphere_count; i++) {
        if intersect_sphere(origin, direction, spheres[i]) > 0.0 {
            return true;
        }
    }
    return false;
}
// ANCHOR_END: nearest_hit

// ANCHOR: checker
// Unit squares in x and z. `s` is a whole number: it is even exactly when
// half of it is whole too (no 64-bit integers in WGSL to take its low bit).
fn checker(point: vec3<f32>) -> vec3<f32> {
    let s = floor(point.x) + floor(point.z);
    let half = s * 0.5;
    return select(params.odd, params.even, floor(half) == half);
}
// ANCHOR_END: checker

// ANCHOR: sky
fn sky(direction: vec3<f32>) -> vec3<f32> {
    let t = sqrt(clamp(direction.y, 0.0, 1.0));
    return (1.0 - t) * params.horizon + t * params.zenith;
}
// ANCHOR_END: sky

// ANCHOR: local_light
// Chapter 1: Lambert's cosine law for the sun, with factor k, plus ambient.
fn local_light(hit: Hit, k: f32) -> vec3<f32> {
    let cos_theta = max(dot(hit.facing_normal, params.to_sun), 0.0);
    let irradiance = k * params.sun_brightness * cos_theta;
    return hit.albedo / PI * irradiance + hit.albedo * AMBIENT;
}
// ANCHOR_END: local_light

// ANCHOR: stack
// A ray waiting on the stack: the lab model's origin, direction, weight and depth
// (and its kind, for the counts).
struct Pending {
    origin: vec3<f32>,
    direction: vec3<f32>,
    weight: f32,
    depth: u32,
    kind: u32,
}

// A GPU has no call stack to recurse on, so the rays still to trace wait
// in a fixed array in each invocation's private memory. Depth first, each
// hit sends on at most two rays: one pops and two push, so the stack grows
// by at most one per level, and `max_depth` places are enough. WGSL
// cannot size this array at run time (a pipeline's `override` constants
// size only workgroup arrays), so the program writes `--max-depth` into
// this line before compiling: a smaller array compiles and runs faster.
const STACK_SIZE: u32 = 64u;

// The most rays traced for one sample, shadow rays included (the core's
// `RAY_BUDGET`): past it no ray is sent on.
const RAY_BUDGET: u32 = 4096u;

// What tracing one sample cost, for the heat maps and the summary line.
struct Tally {
    primary: u32,
    shadow: u32,
    reflected: u32,
    refracted: u32,
    total_internal: u32,
    deepest: u32,
    rays: u32,
    over_budget: u32,
}

// Where a pixel's samples stand when a dispatch ends (see `main`).
struct Progress {
    // The colours of the samples done, summed.
    sum: vec3<f32>,
    // The sample being traced; `params.spp` once the pixel is done.
    sample: u32,
    // That sample's colour so far.
    colour: vec3<f32>,
    // Its rays waiting on the stack: 0 before it starts and when it ends.
    len: u32,
    // Its rays traced so far, and 1 if the ray budget cut it short.
    rays: u32,
    over_budget: u32,
    tally: Tally,
}
// ANCHOR_END: stack

// ANCHOR: trace
// A pixel's samples, one after the other, each traced by the lab model's ray-stack
// loop (one ray per turn: pop it, trace it, push the rays it sends on) with
// the features of the chapter chosen by `params.features`. It stops when
// the pixel is done, or once this dispatch's `params.steps` rays are
// traced; `work` holds where it stands, for the next dispatch (see `main`).
fn trace(
    i: u32,
    j: u32,
    stack: ptr<function, array<Pending, STACK_SIZE>>,
    work: ptr<function, Progress>,
) {
    var steps = 0u;
    while work.sample < params.spp && steps < params.steps {
        if work.len == 0u {
            // A new sample: its primary ray on the stack.
            let direction = camera_ray(i, j, samples[work.sample]);
            (*stack)[0] = Pending(params.eye, direction, 1.0, 1u, PRIMARY);
            work.len = 1u;
        }
        trace_ray(stack, work);
        steps += 1u;
        if work.len == 0u {
            // The sample is done: its colour goes to the pixel's sum.
            work.sum += work.colour;
            work.tally.rays += work.rays;
            work.tally.over_budget += work.over_budget;
            work.colour = vec3<f32>(0.0);
            work.rays = 0u;
            work.over_budget = 0u;
            work.sample += 1u;
        }
    }
}

// One turn of the loop: the ray on top of the stack.
fn trace_ray(
    stack: ptr<function, array<Pending, STACK_SIZE>>,
    work: ptr<function, Progress>,
) {
    work.len -= 1u;
    let ray = (*stack)[work.len];
    count(work, ray.kind);
    work.rays += 1u;
    work.tally.deepest = max(work.tally.deepest, ray.depth);

    let hit = nearest_hit(ray.origin, ray.direction);
    if !hit.found {
        work.colour += ray.weight * sky(ray.direction);
        return;
    }

    // The rays this hit sends on, with the share of the light each
    // takes as its weight (made the ray's own when it is pushed).
    var kept = 1.0;
    var reflected: Pending;
    var transmitted: Pending;

    // ANCHOR: reflection
    // Chapter 3: the mirror share, along the mirror direction.
    let r = hit.reflection;
    if (params.features & REFLECTION) != 0u && r > 0.0 {
        // ANCHOR: todo_reflection "Push the mirror share r: reflected = Pending(start, d, r, 0u, REFLECTED), d the normalised reflect(ray.direction, hit.facing_normal), start params.epsilon along d; the local light keeps the rest (kept -= r)."
        let d = normalize(reflect(ray.direction, hit.facing_normal));
        reflected = Pending(hit.point + d * params.epsilon, d, r, 0u, REFLECTED);
        kept -= r;
        // ANCHOR_END: todo_reflection
    }
    // ANCHOR_END: reflection

    // ANCHOR: shadow_feeler
    // Chapter 2: a feeler towards the sun decides k.
    var k = SUN_LIT;
    if (params.features & SHADOWS) != 0u {
        // ANCHOR: todo_shadow_feeler "Cast the feeler towards the sun (params.to_sun), started params.epsilon along it from hit.point and counted as a SHADOW ray (count, work.rays): k = SUN_IN_SHADOW if any_hit finds anything in the way."
        count(work, SHADOW);
        work.rays += 1u;
        let feeler = hit.point + params.to_sun * params.epsilon;
        if any_hit(feeler, params.to_sun) {
            k = SUN_IN_SHADOW;
        }
        // ANCHOR_END: todo_shadow_feeler
    }
    let local = local_light(hit, k);
    // ANCHOR_END: shadow_feeler

    // ANCHOR: refraction
    // Chapter 4: the transmitted share, bent by Snell's law, or
    // mirrored inside when no refracted direction exists.
    let t = hit.transmission;
    if (params.features & TRANSMISSION) != 0u && t > 0.0 {
        // ANCHOR: todo_refraction "Push the transmitted share t: eta = 1/ior going in (hit.entering), ior coming out; refract(ray.direction, hit.facing_normal, eta) is all zeros past the critical angle, then send t along the mirror direction as TOTAL_INTERNAL, else along the normalised bent ray as REFRACTED, each started params.epsilon along itself; kept -= t."
        let eta = select(hit.ior, 1.0 / hit.ior, hit.entering);
        let bent = refract(ray.direction, hit.facing_normal, eta);
        if all(bent == vec3<f32>(0.0)) {
            let d = normalize(reflect(ray.direction, hit.facing_normal));
            transmitted = Pending(hit.point + d * params.epsilon, d, t, 0u, TOTAL_INTERNAL);
        } else {
            let d = normalize(bent);
            transmitted = Pending(hit.point + d * params.epsilon, d, t, 0u, REFRACTED);
        }
        kept -= t;
        // ANCHOR_END: todo_refraction
    }
    // ANCHOR_END: refraction

    work.colour += ray.weight * kept * local;

    // A weight of 0 marks a ray not sent.
    let sends = reflected.weight > 0.0 || transmitted.weight > 0.0;
    if ray.depth < params.max_depth && sends {
        if work.rays >= RAY_BUDGET {
            work.over_budget = 1u;
            return;
        }
        // The reflected ray first, so the transmitted one is traced first.
        push(stack, work, ray, reflected);
        push(stack, work, ray, transmitted);
    }
}

// Push a ray sent on from `parent`, one level deeper, with the parent's
// weight times its share; a share of 0 is a ray not sent.
fn push(
    stack: ptr<function, array<Pending, STACK_SIZE>>,
    work: ptr<function, Progress>,
    parent: Pending,
    sent: Pending,
) {
    if sent.weight > 0.0 && work.len < STACK_SIZE {
        (*stack)[work.len] = Pending(
            sent.origin,
            sent.direction,
            parent.weight * sent.weight,
            parent.depth + 1u,
            sent.kind,
        );
        work.len += 1u;
    }
}

// One more ray of this kind. (A `switch`, not `kinds[kind]`: an array
// indexed by a number known only at run time must live in memory.)
fn count(work: ptr<function, Progress>, kind: u32) {
    switch kind {
        case 0u: { work.tally.primary += 1u; }
        case 1u: { work.tally.shadow += 1u; }
        case 2u: { work.tally.reflected += 1u; }
        case 3u: { work.tally.refracted += 1u; }
        default: { work.tally.total_internal += 1u; }
    }
}
// ANCHOR_END: trace

// ANCHOR: pixel
// One invocation per pixel, in 8 × 8 tiles: the plain average of the
// pixel's samples, summed in order, in linear light.
//
// A driver may stop a shader that runs too long: lavapipe ends every loop
// once a group of lanes has been round its loops 65535 times in all, and
// a pixel seen through glass among 500 spheres needs far more. So each
// dispatch traces at most `params.steps` rays per pixel (the program sets
// it from the number of spheres), keeps the pixels not done in `progress`
// and `stacks`, and the program dispatches again until none is left.
@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    // The tiles overhang the band's right and bottom edges.
    if id.x >= params.width || id.y >= params.band_rows {
        return;
    }
    let index = id.y * params.width + id.x;
    var work = progress[index];
    if work.sample >= params.spp {
        return; // done in an earlier dispatch
    }
    // WGSL clears every variable it makes: made once per pixel, not once
    // per sample, the stack is cleared once.
    var stack: array<Pending, STACK_SIZE>;
    if work.len > 0u {
        stack = stacks[index];
    }
    trace(id.x, params.first_row + id.y, &stack, &work);
    progress[index] = work;
    if work.sample < params.spp {
        stacks[index] = stack;
        atomicAdd(&unfinished, 1u);
        return;
    }
    let tally = work.tally;
    pixels[index] = vec4<f32>(work.sum / f32(params.spp), 1.0);
    maps[index] = vec2<u32>(tally.deepest, tally.rays);

    let counter = id.y * COUNTERS_PER_ROW;
    atomicAdd(&counts[counter + PRIMARY], tally.primary);
    atomicAdd(&counts[counter + SHADOW], tally.shadow);
    atomicAdd(&counts[counter + REFLECTED], tally.reflected);
    atomicAdd(&counts[counter + REFRACTED], tally.refracted);
    atomicAdd(&counts[counter + TOTAL_INTERNAL], tally.total_internal);
    atomicAdd(&counts[counter + KINDS], tally.over_budget);
}
// ANCHOR_END: pixel
