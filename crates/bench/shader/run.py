#!/usr/bin/env python3
"""The lab's tracers as GLSL fragment shaders on Mesa's llvmpipe, timed
against the workbook's own programs on the same CPU.

  python crates/bench/shader/run.py --shader whitted            time chapter 5 as a shader
  python crates/bench/shader/run.py --shader path --spp 16      time chapter 6 as a shader
  python crates/bench/shader/run.py --shader whitted --whole    one frame, as a whole process
  python crates/bench/shader/run.py --check                     the shaders' images against ours
  python crates/bench/shader/run.py --compare                   the interleaved speed table

See README.md beside this file for the set-up and what each number means.
"""

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[2]
RELEASE = REPO / "target" / "release"

WIDTH, HEIGHT = 800, 600

# A triangle that covers the whole viewport: every pixel gets one fragment,
# and there is no diagonal seam between two triangles to rasterise twice.
VERTEX_SHADER = """
#version 330 core
in vec2 position;
void main() { gl_Position = vec4(position, 0.0, 1.0); }
"""
COVER_ALL = (-1.0, -1.0, 3.0, -1.0, -1.0, 3.0)


def fail(message):
    """One line on stderr and exit code 2, as the workbook's programs do."""
    print(f"run.py: {message}", file=sys.stderr)
    sys.exit(2)




def open_context():
    """A headless OpenGL 3.3 context through EGL: no window, no X server.
    One per process: every shader draws in it (moderngl calls go to the
    context that is current, so two contexts would mix their objects)."""
    try:
        import moderngl
    except ImportError:
        fail("moderngl is not installed: pip install moderngl pillow numpy (see crates/bench/shader/README.md)")
    try:
        return moderngl.create_standalone_context(require=330, backend="egl")
    except Exception as error:  # moderngl raises a bare Exception
        fail(f"no EGL context ({error}): apt-get install -y libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri")


class Shader:
    """One fragment shader, ready to draw 800 x 600 frames on llvmpipe."""

    def __init__(self, ctx, name, width=WIDTH, height=HEIGHT):
        import moderngl
        import numpy as np

        self.moderngl = moderngl
        self.ctx = ctx
        self.name = name
        self.width, self.height = width, height
        # The scene both shaders share; moderngl pastes it in where a shader
        # says #include "lab.glsl" (GLSL has no include of its own).
        ctx.includes["lab.glsl"] = (HERE / "lab.glsl").read_text()
        self.program = ctx.program(
            vertex_shader=VERTEX_SHADER, fragment_shader=(HERE / f"{name}.frag").read_text()
        )
        vbo = ctx.buffer(np.array(COVER_ALL, dtype="f4").tobytes())
        self.vao = ctx.vertex_array(self.program, [(vbo, "2f", "position")])
        # Float targets: the colour (rgb) and the rays traced (a) exactly;
        # the path shader writes its variance into a second one.
        self.targets = [
            ctx.texture((width, height), 4, dtype="f4")
            for _ in range(2 if name == "path" else 1)
        ]
        self.fbo = ctx.framebuffer(color_attachments=self.targets)
        self.uniforms = {}
        self.set("resolution", (float(width), float(height)))

    @property
    def renderer(self):
        return self.ctx.info["GL_RENDERER"]

    def set(self, uniform, value):
        """Set a uniform the shader has (whitted.frag has no spp or seed)."""
        if uniform in self.program:
            self.uniforms[uniform] = value

    def frame(self):
        """Draw one frame and read it back: the read waits until llvmpipe's
        threads have finished every tile, so the time is the whole work."""
        import numpy as np

        self.fbo.use()
        for name, value in self.uniforms.items():
            self.program[name].value = value
        self.vao.render(self.moderngl.TRIANGLES)
        colour = self.fbo.read(components=4, dtype="f4", attachment=0)
        return np.frombuffer(colour, dtype="f4").reshape(self.height, self.width, 4)[::-1]

    def variance(self):
        """The second target of the last frame (the path shader's variance)."""
        import numpy as np

        data = self.fbo.read(components=4, dtype="f4", attachment=1)
        return np.frombuffer(data, dtype="f4").reshape(self.height, self.width, 4)[::-1]


def llvmpipe_threads():
    """How many rendering threads llvmpipe started in this process (it names
    them llvmpipe-0, llvmpipe-1, ...): one per core unless LP_NUM_THREADS says."""
    names = []
    for task in os.listdir("/proc/self/task"):
        try:
            names.append(Path(f"/proc/self/task/{task}/comm").read_text().strip())
        except OSError:
            continue
    return sum(name.startswith("llvmpipe-") for name in names)


def to_srgb8(linear):
    """The lab model's encoding, for the path shader's linear radiance."""
    import numpy as np

    c = np.clip(np.nan_to_num(linear, nan=0.0), 0.0, 1.0).astype("f4")
    v = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)
    return np.floor(255.0 * v + 0.5).astype("u1")


def save_png(rgb8, path):
    from PIL import Image

    Image.fromarray(rgb8, "RGB").save(path)


def render(name, frames, spp, seed, out, whole=False, max_depth=10):
    """Render with one shader: a warm-up frame (the JIT compiles the shader
    at its first draw), then `frames` timed ones; write the last as PNG."""
    import numpy as np

    shader = Shader(open_context(), name)
    shader.set("spp", spp)
    shader.set("seed", seed)
    shader.set("max_depth", max_depth)
    if not whole:
        shader.frame()
        print(f"GL_RENDERER: {shader.renderer}; cores: {os.cpu_count()}; "
              f"llvmpipe threads: {llvmpipe_threads()} (LP_NUM_THREADS {os.environ.get('LP_NUM_THREADS', 'unset')})")
    times = []
    for _ in range(1 if whole else frames):
        start = time.perf_counter()
        image = shader.frame()
        times.append(time.perf_counter() - start)
    rays = float(image[..., 3].astype("f8").sum())
    out.mkdir(parents=True, exist_ok=True)
    if name == "whitted":
        # The shader encoded the pixel already: rgb are levels / 255.
        rgb8 = np.rint(image[..., :3] * 255.0).astype("u1")
    else:
        rgb8 = to_srgb8(image[..., :3])
        np.save(out / "path-radiance.npy", np.ascontiguousarray(image[..., :3]))
        np.save(out / "path-variance.npy", np.ascontiguousarray(shader.variance()[..., :3]))
    save_png(rgb8, out / f"{name}.png")
    if not whole:
        ms = statistics.median(times) * 1e3
        paths = WIDTH * HEIGHT * (spp if name == "path" else 5)
        print(
            f"{name}: {WIDTH}x{HEIGHT}, {paths:,} {'paths' if name == 'path' else 'camera rays'}, "
            f"{rays:,.0f} rays, median {ms:.1f} ms over {len(times)} frames, "
            f"{rays / ms / 1e3:.1f} Mrays/s"
            + (f", {paths / ms / 1e3:.2f} M paths/s" if name == "path" else "")
        )
        print(f"wrote {out / (name + '.png')}")
    return shader, image, times


# ------------------------------------------------------------------ check


def agreement(ours, reference):
    """The lab model's tolerance (src/tolerance.rs): the share of pixels within 3
    of 255 in every channel, the mean absolute difference over every channel,
    and the largest difference."""
    import numpy as np

    diff = np.abs(ours.astype("i2") - reference.astype("i2"))
    within = float((diff.max(axis=2) <= 3).mean())
    return within, float(diff.mean()), int(diff.max()), float((diff.max(axis=2) == 0).mean())


def read_exr_rgb(path):
    import numpy as np
    import OpenEXR

    with OpenEXR.File(str(path)) as f:
        channels = f.channels()
        if "RGB" in channels:
            return np.asarray(channels["RGB"].pixels, dtype="f8")
        if "RGBA" in channels:
            return np.asarray(channels["RGBA"].pixels, dtype="f8")[..., :3]
        return np.stack([np.asarray(channels[c].pixels, dtype="f8") for c in "RGB"], axis=2)


def run_ours(binary, args, out):
    command = [str(RELEASE / binary), *args, "--out", str(out)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail(f"{' '.join(command)} failed: {done.stderr.strip()}")
    return done.stdout


def check(spp, seed):
    """Compare each shader's image with the workbook's own."""
    import numpy as np
    from PIL import Image

    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        # Chapter 5: the lab model's tolerance on the 8-bit images.
        run_ours("ch05-antialiasing", ["--no-diagrams"], tmp / "ch05")
        ours = np.asarray(Image.open(tmp / "ch05" / "render.png").convert("RGB"))
        _, shaded, _ = render("whitted", 1, 5, seed, tmp / "shader", whole=True)
        theirs = np.asarray(Image.open(tmp / "shader" / "whitted.png").convert("RGB"))
        within, mean, worst, identical = agreement(theirs, ours)
        verdict = "meets" if within >= 0.995 and mean < 0.5 else "FAILS"
        print(
            f"whitted shader vs ch05-antialiasing: {within:.4%} of pixels within 3/255, "
            f"mean difference {mean:.4f}/255, largest {worst}, identical {identical:.4%}: "
            f"{verdict} the lab model's tolerance"
        )
        ch05_rays = re.search(r"([\d,]+) rays", run_ours("ch05-antialiasing", ["--no-diagrams"], tmp / "ch05b"))
        shader_rays = float(shaded[..., 3].astype("f8").sum())
        if ch05_rays:
            print(f"  rays traced: shader {shader_rays:,.0f}, ch05 {ch05_rays.group(1)}")

        # Chapter 6: the same estimator, other random numbers; compare means
        # with their standard errors (ours from variance.exr, the shader's
        # from its own second target).
        args = ["--width", str(WIDTH), "--height", str(HEIGHT), "--spp", str(spp), "--no-diagrams"]
        ch06_rays = number(r"([\d,]+) rays", run_ours("ch06-path-tracing", args, tmp / "ch06"))
        a = read_exr_rgb(tmp / "ch06" / "render.exr")
        var_a = read_exr_rgb(tmp / "ch06" / "variance.exr")
        _, traced, _ = render("path", 1, spp, seed, tmp / "shader", whole=True)
        b = np.load(tmp / "shader" / "path-radiance.npy").astype("f8")
        var_b = np.load(tmp / "shader" / "path-variance.npy").astype("f8")
        n = a.shape[0] * a.shape[1]
        print(f"path shader vs ch06-path-tracing, {spp} paths per pixel, {WIDTH}x{HEIGHT}:")
        for c, name in enumerate("RGB"):
            ma, mb = a[..., c].mean(), b[..., c].mean()
            se = np.sqrt(var_a[..., c].sum() + var_b[..., c].sum()) / n
            print(f"  image mean {name}: ch06 {ma:.5f}, shader {mb:.5f}, difference {mb - ma:+.5f} = {(mb - ma) / se:+.2f} standard errors")
        block = 50
        h, w = a.shape[0] // block, a.shape[1] // block

        def blocks(x):
            return x[: h * block, : w * block].reshape(h, block, w, block, 3)

        mean_a, mean_b = blocks(a).mean(axis=(1, 3)), blocks(b).mean(axis=(1, 3))
        se = np.sqrt(blocks(var_a).sum(axis=(1, 3)) + blocks(var_b).sum(axis=(1, 3))) / block**2
        z = (mean_b - mean_a) / np.where(se > 0, se, np.inf)
        k = z.size
        print(
            f"  {w}x{h} blocks of {block}x{block} pixels, 3 channels ({k} z-scores): "
            f"mean z {z.mean():+.3f}, rms z {np.sqrt((z**2).mean()):.3f}, largest |z| {np.abs(z).max():.2f}, "
            f"|z| > 3: {int((np.abs(z) > 3).sum())} (expected {k * 0.0027:.1f} by chance)"
        )
        rel = np.abs(mean_b - mean_a) / np.maximum(mean_a, 1e-6)
        print(f"  largest relative block difference {rel.max():.3%}, median {np.median(rel):.3%}")
        px = np.abs(b - a) / np.sqrt(var_a + var_b + 1e-30)
        print(
            f"  per-pixel |z| > 4: {(px > 4).mean():.4%} of pixel channels (a normal's share is 0.006 %; "
            f"each pixel's variance comes from its own {spp} samples, so the tails are heavier)"
        )
        shader_rays = float(traced[..., 3].astype("f8").sum())
        print(f"  rays traced: shader {shader_rays:,.0f}, ch06 {ch06_rays:,.0f} ({shader_rays / ch06_rays - 1:+.3%})")


# ---------------------------------------------------------------- compare


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed_process(command):
    """Wall-clock time and processor time (user + sys, every thread) of a
    whole process, and what it printed."""
    cpu, start = children_cpu(), time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    elapsed, cpu = time.perf_counter() - start, children_cpu() - cpu
    if done.returncode != 0:
        fail(f"{' '.join(map(str, command))} failed: {done.stderr.strip()}")
    return elapsed, cpu, done.stdout


def number(pattern, text):
    found = re.search(pattern, text)
    return float(found.group(1).replace(",", "")) if found else float("nan")


def own_time_ms(stdout):
    found = re.search(r"rays?\b.*? in ([\d.]+) (ms|s)\b", stdout)
    if not found:
        return float("nan")
    return float(found.group(1)) * (1.0 if found.group(2) == "ms" else 1e3)


def compare(rounds, spp, seed, only="abcdehfg"):
    """Time (a)–(h) alternately, round after round, so that the machine's
    drift and the other engineers' builds fall on every variant alike."""
    ctx = open_context()
    whitted = Shader(ctx, "whitted")
    path = Shader(ctx, "path")
    path.set("spp", spp)
    path.set("seed", seed)
    path.set("max_depth", 10)
    whitted_rays = float(whitted.frame()[..., 3].astype("f8").sum())  # warm-up and count
    path_rays = float(path.frame()[..., 3].astype("f8").sum())
    print(f"GL_RENDERER: {whitted.renderer}; cores: {os.cpu_count()}; "
          f"llvmpipe threads: {llvmpipe_threads()} (LP_NUM_THREADS {os.environ.get('LP_NUM_THREADS', 'unset')})")
    # The machine's load before and after the rounds, printed with the
    # table: other work on the machine slows both sides, and not equally.
    load_before = os.getloadavg()[0]
    tmp = Path(tempfile.mkdtemp(prefix="raylab-shader-"))
    size = ["--width", str(WIDTH), "--height", str(HEIGHT)]
    variants = {
        "a": ("whitted shader frame", None),
        "b": ("ch05-antialiasing process", [RELEASE / "ch05-antialiasing", *size, "--no-diagrams", "--out", tmp / "b"]),
        "c": ("ch07-eight-rays process", [RELEASE / "ch07-eight-rays", *size, "--no-diagrams", "--out", tmp / "c"]),
        "d": (f"path shader frame, {spp} spp", None),
        "e": (f"ch06-path-tracing process, {spp} spp",
              [RELEASE / "ch06-path-tracing", *size, "--spp", str(spp), "--no-diagrams", "--out", tmp / "e"]),
        "h": (f"ch08-eight-paths process, {spp} spp",
              [RELEASE / "ch08-eight-paths", *size, "--spp", str(spp), "--no-diagrams", "--out", tmp / "h"]),
        "f": ("whitted shader whole process",
              [sys.executable, HERE / "run.py", "--shader", "whitted", "--whole", "--out", tmp / "f"]),
        "g": (f"path shader whole process, {spp} spp",
              [sys.executable, HERE / "run.py", "--shader", "path", "--spp", str(spp), "--seed", str(seed),
               "--whole", "--out", tmp / "g"]),
    }
    variants = {k: v for k, v in variants.items() if k in only}
    for _, command in variants.values():
        if command is not None and Path(command[0]).parent == RELEASE and not Path(command[0]).exists():
            fail(f"{command[0]} is missing: cargo build --release -p {Path(command[0]).name}")
    times = {k: [] for k in variants}
    cpu = {k: [] for k in variants}
    internal = {k: [] for k in variants}
    rays = {"a": whitted_rays, "d": path_rays, "f": whitted_rays, "g": path_rays}
    for r in range(rounds):
        for key, (_, command) in variants.items():
            if command is None:
                shader = whitted if key == "a" else path
                # process_time counts every thread of this process, and so
                # llvmpipe's rendering threads.
                processor, start = time.process_time(), time.perf_counter()
                shader.frame()
                times[key].append(time.perf_counter() - start)
                cpu[key].append(time.process_time() - processor)
                continue
            elapsed, processor, stdout = timed_process(command)
            times[key].append(elapsed)
            cpu[key].append(processor)
            if key in "bceh":
                # Our programs count their rays and say so.
                rays[key] = number(r"([\d,]+) rays", stdout)
            # The program's own render time, without start-up and files
            # (chapters 5 and 7 print it in ms, chapter 6 in s).
            internal[key].append(own_time_ms(stdout))
        print(f"round {r + 1}/{rounds}: " + ", ".join(f"{k} {times[k][-1] * 1e3:.0f} ms" for k in variants),
              file=sys.stderr)

    median = {k: statistics.median(v) * 1e3 for k, v in times.items()}
    paths = WIDTH * HEIGHT * spp
    print()
    print(f"{WIDTH}x{HEIGHT}, {rounds} interleaved rounds, medians ({os.cpu_count()} cores; "
          f"load average {load_before:.1f} before, {os.getloadavg()[0]:.1f} after)")
    print()
    print("| | what | median ms | processor ms | rays | Mrays/s | M paths/s | program's own render ms |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for key, (what, _) in variants.items():
        mrays = rays[key] / median[key] / 1e3
        mpaths = f"{paths / median[key] / 1e3:.2f}" if key in "degh" else ""
        own = f"{statistics.median(internal[key]):.0f}" if key in "bceh" else ""
        processor = statistics.median(cpu[key]) * 1e3
        print(f"| {key} | {what} | {median[key]:.0f} | {processor:.0f} | {rays[key]:,.0f} | {mrays:.1f} | {mpaths} | {own} |")
    print()

    def ratio(x, y, of=times):
        # Round by round, then the median: each pair ran seconds apart.
        return statistics.median(p / q for p, q in zip(of[x], of[y]))

    lines = [
        ("ac", lambda: f"whitted shader frame / ch07 process (issue 15 asks >= 3): {ratio('a', 'c'):.2f}x "
                       f"(processor time: {ratio('a', 'c', cpu):.2f}x)"),
        ("fc", lambda: f"whitted shader whole process / ch07 process: {ratio('f', 'c'):.2f}x"),
        ("ab", lambda: f"whitted shader frame / ch05 process: {ratio('a', 'b'):.2f}x "
                       f"(processor time: {ratio('a', 'b', cpu):.2f}x)"),
        ("dh", lambda: f"path shader frame / ch08 process (issue 42 asks >= 2): {ratio('d', 'h'):.2f}x "
                       f"(processor time: {ratio('d', 'h', cpu):.2f}x) "
                       f"(ch08 {paths / median['h'] / 1e3:.2f} vs shader {paths / median['d'] / 1e3:.2f} M paths/s, "
                       f"{rays['h'] / median['h'] / 1e3:.1f} vs {rays['d'] / median['d'] / 1e3:.1f} Mrays/s)"),
        ("de", lambda: f"path shader frame / ch06 process: {ratio('d', 'e'):.2f}x "
                       f"(processor time: {ratio('d', 'e', cpu):.2f}x)"),
        ("gh", lambda: f"path shader whole process / ch08 process: {ratio('g', 'h'):.2f}x"),
        ("eh", lambda: f"ch06 process (one path at a time) / ch08 process (eight): {ratio('e', 'h'):.2f}x "
                       f"(processor time: {ratio('e', 'h', cpu):.2f}x; the renders alone: {ratio('e', 'h', internal):.2f}x)"),
    ]
    for needs, line in lines:
        if all(k in variants for k in needs):
            print(line())


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--shader", choices=["whitted", "path"], help="render and time one shader")
    parser.add_argument("--whole", action="store_true",
                        help="one frame, no warm-up, quietly: for timing a whole shader process")
    parser.add_argument("--check", action="store_true", help="compare both shaders' images with ch05's and ch06's")
    parser.add_argument("--compare", action="store_true", help="the interleaved speed table, (a) to (h)")
    parser.add_argument("--frames", type=int, default=10, help="timed frames after the warm-up [10]")
    parser.add_argument("--rounds", type=int, default=15, help="rounds of --compare [15]")
    parser.add_argument("--only", default="abcdehfg",
                        help="the variants --compare times, by letter (e.g. dh: the path shader's frame and ch08) [abcdehfg]")
    parser.add_argument("--spp", type=int, default=16, help="paths per pixel of the path shader [16]")
    parser.add_argument("--seed", type=int, default=1, help="seed of the path shader's random numbers [1]")
    parser.add_argument("--out", type=Path, default=Path("out") / "shader", help="folder to write into [out/shader]")
    args = parser.parse_args()
    if not 1 <= args.spp <= 4096:
        fail(f"--spp {args.spp}: paths per pixel must be 1 to 4096")
    if args.frames < 1 or args.rounds < 1:
        fail("--frames and --rounds must be at least 1")
    if not args.only or any(k not in "abcdefgh" for k in args.only):
        fail(f"--only {args.only}: name variants by their letters, a to h")
    if args.compare:
        compare(args.rounds, args.spp, args.seed, args.only)
    elif args.check:
        check(args.spp, args.seed)
    elif args.shader:
        render(args.shader, args.frames, args.spp, args.seed, args.out, whole=args.whole)
    else:
        fail("say what to do: --shader whitted|path, --check or --compare (see --help)")


if __name__ == "__main__":
    main()
