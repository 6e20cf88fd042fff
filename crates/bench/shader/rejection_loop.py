#!/usr/bin/env python3
"""A rejection loop on llvmpipe: the same uniform points in the unit disc,
drawn three ways, should give E[r^2] = 0.5 each. On Mesa 22.3.6's llvmpipe
(LLVM 15, 256 bits) the unbounded loop does not; see README.md.

  python crates/bench/shader/rejection_loop.py
"""

import numpy as np

from run import COVER_ALL, VERTEX_SHADER, open_context

PCG = """
#version 330 core
out vec4 result;
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
float uniform01(inout uint state) {
    state = state * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    word = (word >> 22u) ^ word;
    return float(word >> 8u) * (1.0 / 16777216.0);
}
void main() {
    uint state = pcg_hash(uint(gl_FragCoord.y) * 800u + uint(gl_FragCoord.x));
    float x, y, r2;
    LOOP {
        x = 2.0 * uniform01(state) - 1.0;
        y = 2.0 * uniform01(state) - 1.0;
        r2 = x * x + y * y;
        if (r2 < 1.0) break;
    }
    result = vec4(r2, float(r2 < 1.0), 0.0, 0.0);
}
"""

LOOPS = {
    "unbounded, for (;;)": "for (;;)",
    "bounded, for (int k = 0; k < 16; k++)": "for (int k = 0; k < 16; k++)",
}


def mean_r2(ctx, loop):
    program = ctx.program(vertex_shader=VERTEX_SHADER, fragment_shader=PCG.replace("LOOP", loop))
    vbo = ctx.buffer(np.array(COVER_ALL, dtype="f4").tobytes())
    vao = ctx.vertex_array(program, [(vbo, "2f", "position")])
    fbo = ctx.framebuffer(color_attachments=[ctx.texture((800, 600), 4, dtype="f4")])
    fbo.use()
    vao.render()
    pixels = np.frombuffer(fbo.read(components=4, dtype="f4"), dtype="f4").reshape(-1, 4)
    return pixels[:, 0].astype("f8").mean(), pixels[:, 1].mean()


def main():
    ctx = open_context()
    print(f"GL_RENDERER: {ctx.info['GL_RENDERER']}, {ctx.info['GL_VERSION']}")
    # E[r^2] of one uniform point in the disc is 1/2; over 480,000 pixels
    # its standard error is sqrt(1/12 / 480000) = 0.0004.
    for name, loop in LOOPS.items():
        r2, inside = mean_r2(ctx, loop)
        print(f"{name}: E[r^2] = {r2:.4f} (expected 0.5000 +- 0.0004), inside the disc: {inside:.4f}")


if __name__ == "__main__":
    main()
