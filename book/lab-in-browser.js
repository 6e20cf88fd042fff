// The lab in your browser (lab-in-browser.md): chapter 10's own
// tracer.wgsl, run by the browser's WebGPU, and the lab's three tasks
// checked as `learn check shader` checks them. Plain JavaScript, no
// library, no network.
//
// Everything it reads comes from figures/lab-in-browser/lab-data.js, which
// the main job writes (crates/workbook/src/lab_page.rs): the shader as the
// file is, its blank, the scenes as chapter 10 packs them (so the byte
// layout is written once, in Rust) and the chapters' CPU renders. What
// happens on the GPU is chapter 10's `Gpu::render` (chapters/10-gpu/src/
// gpu.rs) step for step: the same buffers, the same bands of rows, the
// same dispatches repeated until no pixel is left unfinished.
(function () {
  "use strict";

  var LAB = null;
  var STORE = "raylab.lab-in-browser.shader";

  // --- bytes and pictures -------------------------------------------------

  function bytes(base64) {
    var text = atob(base64);
    var out = new Uint8Array(text.length);
    for (var i = 0; i < text.length; i++) out[i] = text.charCodeAt(i);
    return out;
  }

  // A PNG the page carries, as RGB bytes. Decoded from a Blob the page
  // made itself, so the canvas is not "tainted" as an image read from disk
  // would be, and no colour conversion touches the bytes.
  function decodePng(base64) {
    var blob = new Blob([bytes(base64)], { type: "image/png" });
    return createImageBitmap(blob, { colorSpaceConversion: "none", premultiplyAlpha: "none" })
      .then(function (bitmap) {
        var canvas = document.createElement("canvas");
        canvas.width = bitmap.width;
        canvas.height = bitmap.height;
        var context = canvas.getContext("2d");
        context.drawImage(bitmap, 0, 0);
        var rgba = context.getImageData(0, 0, bitmap.width, bitmap.height).data;
        return { width: bitmap.width, height: bitmap.height, rgb: rgbOf(rgba) };
      });
  }

  function rgbOf(rgba) {
    var rgb = new Uint8Array(rgba.length / 4 * 3);
    for (var i = 0, j = 0; i < rgba.length; i += 4, j += 3) {
      rgb[j] = rgba[i]; rgb[j + 1] = rgba[i + 1]; rgb[j + 2] = rgba[i + 2];
    }
    return rgb;
  }

  function draw(canvas, image) {
    canvas.width = image.width;
    canvas.height = image.height;
    var context = canvas.getContext("2d");
    var data = context.createImageData(image.width, image.height);
    for (var i = 0, j = 0; j < image.rgb.length; i += 4, j += 3) {
      data.data[i] = image.rgb[j]; data.data[i + 1] = image.rgb[j + 1];
      data.data[i + 2] = image.rgb[j + 2]; data.data[i + 3] = 255;
    }
    context.putImageData(data, 0, 0);
  }

  // The core's encoder (raylab::srgb::encode_channel): a channel's byte is
  // the number of thresholds at or below it, which gives the core's byte
  // for every f32 with no power computed in doubles.
  function encode(c) {
    if (!(c > 0)) return 0; // 0, negatives and NaN
    var t = LAB.srgbThresholds, low = 0, high = t.length;
    while (low < high) {
      var mid = (low + high) >> 1;
      if (t[mid] <= c) low = mid + 1; else high = mid;
    }
    return low;
  }

  // The lab model's tolerance (raylab::tolerance::compare), and where the
  // largest change is.
  function compare(ours, reference) {
    var tol = LAB.tolerance, a = ours.rgb, b = reference.rgb;
    var pixels = ours.width * ours.height, within = 0, sum = 0, max = 0, worst = -1;
    for (var p = 0; p < pixels; p++) {
      var change = 0;
      for (var c = 0; c < 3; c++) {
        var d = Math.abs(a[3 * p + c] - b[3 * p + c]);
        sum += d;
        if (d > change) change = d;
      }
      if (change <= tol.withinLevels) within++;
      if (change > max) { max = change; worst = p; }
    }
    var share = within / pixels, mean = sum / (3 * pixels);
    return {
      within: share, mean: mean, max: max,
      worst: worst < 0 ? null : { x: worst % ours.width, y: Math.floor(worst / ours.width) },
      passes: share >= tol.shareWithin && mean < tol.meanBelow
    };
  }

  // learn's signed difference (crates/learn/src/compare.rs): black where
  // the two agree, red where yours is brighter, blue where darker.
  function difference(ours, reference) {
    var out = new Uint8Array(ours.rgb.length), gain = LAB.differenceGain;
    for (var j = 0; j < out.length; j += 3) {
      var same = true, signed = 0;
      for (var c = 0; c < 3; c++) {
        signed += ours.rgb[j + c] - reference.rgb[j + c];
        if (ours.rgb[j + c] !== reference.rgb[j + c]) same = false;
      }
      signed /= 3;
      var strength = Math.min(Math.abs(signed) / 255 * gain, 1);
      var level = same ? 0 : Math.floor(40 + 215 * strength);
      if (!same && signed >= 0) { out[j] = level; out[j + 1] = Math.floor(level / 5); }
      else { out[j + 1] = Math.floor(level / 3); out[j + 2] = level; }
    }
    return { width: ours.width, height: ours.height, rgb: out };
  }

  function percent(share) { return (share * 100).toFixed(2) + " %"; }

  function agreementText(agreement) {
    return percent(agreement.within) + " of pixels within " + LAB.tolerance.withinLevels +
      " levels (" + percent(LAB.tolerance.shareWithin) + " needed), mean difference " +
      agreement.mean.toFixed(3) + " (under " + LAB.tolerance.meanBelow + " needed), largest " +
      agreement.max + (agreement.worst ? " at (" + agreement.worst.x + ", " + agreement.worst.y + ")" : "");
  }

  // --- the GPU: chapter 10's Gpu, in WebGPU --------------------------------

  var gpu = null;

  function openGpu() {
    if (!navigator.gpu) return Promise.reject(new Error("navigator.gpu is missing"));
    return navigator.gpu.requestAdapter().then(function (adapter) {
      if (!adapter) throw new Error("no WebGPU adapter");
      // Ask for the adapter's biggest buffers, as chapter 10 does: big
      // images need big storage buffers.
      var limits = {
        maxStorageBufferBindingSize: adapter.limits.maxStorageBufferBindingSize,
        maxBufferSize: adapter.limits.maxBufferSize
      };
      return adapter.requestDevice({ requiredLimits: limits }).then(function (device) {
        var storage = function (binding, readOnly) {
          return { binding: binding, visibility: GPUShaderStage.COMPUTE,
                   buffer: { type: readOnly ? "read-only-storage" : "storage" } };
        };
        var layout = device.createBindGroupLayout({
          entries: [{ binding: 0, visibility: GPUShaderStage.COMPUTE, buffer: { type: "uniform" } },
                    storage(1, true), storage(2, true), storage(3), storage(4), storage(5),
                    storage(6), storage(7), storage(8)]
        });
        var info = adapter.info || {};
        gpu = {
          device: device, layout: layout,
          pipelineLayout: device.createPipelineLayout({ bindGroupLayouts: [layout] }),
          adapter: [info.vendor, info.architecture, info.description].filter(Boolean).join(" ") || "WebGPU",
          lost: false
        };
        device.lost.then(function (why) {
          gpu.lost = true;
          say("The GPU device was lost (" + why.message + "): reload the page.");
        });
        return gpu;
      });
    });
  }

  // chapter 10's Source::with_stack_size: the ray stack sized for the depth
  // on its own line, every other line where it was.
  function withStackSize(text, maxDepth) {
    return text.split("\n").map(function (line) {
      return line.trimStart().indexOf(LAB.stackSizeLine) === 0
        ? LAB.stackSizeLine + maxDepth + "u;" : line;
    }).join("\n");
  }

  // Compile the shader for `maxDepth`: a pipeline, or the compiler's
  // messages with their lines and columns.
  var compiled = new Map();
  function compile(text, maxDepth) {
    var key = maxDepth + "\n" + text;
    if (compiled.has(key)) return compiled.get(key);
    var device = gpu.device;
    var module = device.createShaderModule({ code: withStackSize(text, maxDepth) });
    var made = module.getCompilationInfo().then(function (info) {
      var errors = info.messages.filter(function (m) { return m.type === "error"; })
        .map(function (m) { return { line: m.lineNum, column: m.linePos, message: m.message }; });
      if (errors.length) return { errors: errors };
      device.pushErrorScope("validation");
      return device.createComputePipelineAsync({
        layout: gpu.pipelineLayout, compute: { module: module, entryPoint: "main" }
      }).then(function (pipeline) {
        return device.popErrorScope().then(function (error) {
          if (error) return { errors: [{ line: 0, column: 0, message: error.message }] };
          return { pipeline: pipeline, maxDepth: maxDepth };
        });
      }, function (error) {
        return device.popErrorScope().then(function () {
          return { errors: [{ line: 0, column: 0, message: error.message }] };
        });
      });
    });
    if (compiled.size > 12) compiled.clear();
    compiled.set(key, made);
    return made;
  }

  function buffer(size, usage, contents) {
    var b = gpu.device.createBuffer({ size: Math.max(4, Math.ceil(size / 4) * 4), usage: usage,
                                      mappedAtCreation: !!contents });
    if (contents) { new Uint8Array(b.getMappedRange()).set(contents); b.unmap(); }
    return b;
  }

  function readBack(b) {
    return b.mapAsync(GPUMapMode.READ).then(function () {
      var copy = b.getMappedRange().slice(0);
      b.unmap();
      return copy;
    });
  }

  // One frame (chapter 10's Gpu::render): `settings` are the size, depth,
  // epsilon, rays per pixel, features and scene ("lab" or "underWater").
  function renderFrame(tracer, settings) {
    var U = GPUBufferUsage, P = LAB.params, device = gpu.device, queue = device.queue;
    var scene = LAB.scenes[settings.scene];
    var params = bytes(scene.params), view = new DataView(params.buffer);
    view.setUint32(P.width, settings.width, true);
    view.setUint32(P.height, settings.height, true);
    view.setFloat32(P.epsilon, settings.epsilon, true);
    view.setUint32(P.maxDepth, settings.maxDepth, true);
    view.setUint32(P.spp, settings.spp, true);
    view.setUint32(P.features, settings.features, true);
    var spheres = bytes(scene.spheres), samples = bytes(LAB.samples[settings.spp]);
    var width = settings.width, height = settings.height;
    // Bands of rows, as many as fit the biggest buffer, the ray stacks.
    var limit = Math.min(device.limits.maxStorageBufferBindingSize, device.limits.maxBufferSize);
    var stackBytes = tracer.maxDepth * LAB.pendingSize;
    var rowBytes = width * Math.max(stackBytes, 16);
    var rowsPerBand = Math.max(1, Math.min(height, Math.floor(Math.min(limit, 32 << 20) / rowBytes)));
    var bandPixels = width * rowsPerBand;
    var progress = buffer(bandPixels * LAB.progressSize, U.STORAGE | U.COPY_DST);
    var stacks = buffer(bandPixels * stackBytes, U.STORAGE);
    var unfinished = buffer(4, U.STORAGE | U.COPY_DST | U.COPY_SRC);
    var spheresBuffer = buffer(spheres.length, U.STORAGE, spheres);
    var samplesBuffer = buffer(samples.length, U.STORAGE, samples);
    var linear = new Float32Array(width * height * 3);
    var rays = 0, dispatches = 0, start = performance.now(), dispatchTime = 0;
    var made = [progress, stacks, unfinished, spheresBuffer, samplesBuffer];

    function band(firstRow) {
      if (firstRow >= height) return Promise.resolve();
      var rows = Math.min(rowsPerBand, height - firstRow), pixels = width * rows;
      view.setUint32(P.firstRow, firstRow, true);
      view.setUint32(P.bandRows, rows, true);
      var uniform = buffer(params.length, U.UNIFORM, params);
      var colours = buffer(pixels * 16, U.STORAGE | U.COPY_SRC);
      var maps = buffer(pixels * 8, U.STORAGE);
      var counts = buffer(height * 6 * 4, U.STORAGE | U.COPY_SRC);
      made.push(uniform, colours, maps, counts);
      var group = device.createBindGroup({
        layout: gpu.layout,
        entries: [uniform, spheresBuffer, samplesBuffer, colours, maps, counts, progress, stacks, unfinished]
          .map(function (b, i) { return { binding: i, resource: { buffer: b } }; })
      });
      var bandStart = performance.now();
      var first = device.createCommandEncoder();
      first.clearBuffer(progress);
      queue.submit([first.finish()]);
      // Again, until no pixel is left unfinished (see `main` in tracer.wgsl).
      function dispatch() {
        var encoder = device.createCommandEncoder();
        encoder.clearBuffer(unfinished);
        var pass = encoder.beginComputePass();
        pass.setPipeline(tracer.pipeline);
        pass.setBindGroup(0, group);
        pass.dispatchWorkgroups(Math.ceil(width / LAB.tile), Math.ceil(rows / LAB.tile), 1);
        pass.end();
        var read = buffer(4, U.MAP_READ | U.COPY_DST);
        made.push(read);
        encoder.copyBufferToBuffer(unfinished, 0, read, 0, 4);
        queue.submit([encoder.finish()]);
        dispatches++;
        return readBack(read).then(function (left) {
          if (new Uint32Array(left)[0] > 0) return dispatch();
        });
      }
      return dispatch().then(function () {
        dispatchTime += performance.now() - bandStart;
        var encoder = device.createCommandEncoder();
        var colourRead = buffer(pixels * 16, U.MAP_READ | U.COPY_DST);
        var countRead = buffer(height * 6 * 4, U.MAP_READ | U.COPY_DST);
        made.push(colourRead, countRead);
        encoder.copyBufferToBuffer(colours, 0, colourRead, 0, pixels * 16);
        encoder.copyBufferToBuffer(counts, 0, countRead, 0, height * 6 * 4);
        queue.submit([encoder.finish()]);
        return Promise.all([readBack(colourRead), readBack(countRead)]);
      }).then(function (results) {
        var rgba = new Float32Array(results[0]), n = new Uint32Array(results[1]);
        for (var p = 0; p < pixels; p++) {
          for (var c = 0; c < 3; c++) linear[3 * (firstRow * width + p) + c] = rgba[4 * p + c];
        }
        for (var k = 0; k < n.length; k++) if (k % 6 < 5) rays += n[k];
        return band(firstRow + rows);
      });
    }

    return band(0).then(function () {
      made.forEach(function (b) { b.destroy(); });
      // The core's encoder, as chapter 10's: a pixel that came back NaN or
      // infinite is black.
      var rgb = new Uint8Array(width * height * 3);
      for (var p = 0; p < width * height; p++) {
        var r = linear[3 * p], g = linear[3 * p + 1], b = linear[3 * p + 2];
        var finite = isFinite(r) && isFinite(g) && isFinite(b);
        rgb[3 * p] = finite ? encode(r) : 0;
        rgb[3 * p + 1] = finite ? encode(g) : 0;
        rgb[3 * p + 2] = finite ? encode(b) : 0;
      }
      var total = performance.now() - start;
      return { width: width, height: height, rgb: rgb, rays: rays, dispatches: dispatches,
               dispatchMs: dispatchTime, frameMs: total };
    }, function (error) {
      made.forEach(function (b) { b.destroy(); });
      throw error;
    });
  }

  // --- the page -----------------------------------------------------------

  function element(tag, attributes, children) {
    var e = document.createElement(tag);
    Object.keys(attributes || {}).forEach(function (k) {
      if (k === "text") e.textContent = attributes[k]; else e.setAttribute(k, attributes[k]);
    });
    (children || []).forEach(function (c) { e.appendChild(c); });
    return e;
  }

  var statusLine = null;
  function say(text) { if (statusLine) statusLine.textContent = text; }

  function labelled(text, control) {
    return element("label", {}, [document.createTextNode(text + " "), control]);
  }

  function select(id, options, value) {
    var s = element("select", { id: id });
    options.forEach(function (o) {
      var option = element("option", { value: String(o[0]), text: o[1] });
      if (String(o[0]) === String(value)) option.selected = true;
      s.appendChild(option);
    });
    return s;
  }

  function figure(caption, canvas) {
    return element("figure", { "class": "lab-figure" },
      [canvas, element("figcaption", { text: caption })]);
  }

  function thousands(n) { return String(n).replace(/\B(?=(\d{3})+(?!\d))/g, ","); }

  // Only one thing on the GPU at a time: renders and checks queue here.
  var queueTail = Promise.resolve();
  function onGpu(job) {
    var run = queueTail.then(job, job);
    queueTail = run.then(function () {}, function () {});
    return run;
  }

  // The viewer: the lab scene as chapters 1–5, with the knobs.
  function viewer(box, references, editorText) {
    var chapter = select("lab-chapter", LAB.chapters.map(function (c) {
      return [c.number, "chapter " + c.number + " (" + c.binary + ")"];
    }), 5);
    var depth = element("input", { id: "lab-depth", type: "number", min: "1", max: "64", value: "10" });
    var epsilon = select("lab-epsilon", [[0, "0"], [1e-6, "1e-6"], [1e-5, "1e-5"], [1e-4, "1e-4"],
                                         [1e-3, "1e-3"], [1e-2, "1e-2"]], 1e-4);
    var spp = select("lab-spp", [[1, "1 (the pixel centre)"], [4, "4 (a 2 × 2 grid)"],
                                 [5, "5 (the lab's five)"], [9, "9 (3 × 3)"], [16, "16 (4 × 4)"]], 5);
    var size = select("lab-size", [["160x120", "160 × 120"], ["320x240", "320 × 240"],
                                   ["800x600", "800 × 600"]], LAB.compare.width + "x" + LAB.compare.height);
    var which = select("lab-which", [["chapter", "tracer.wgsl, the chapter's"],
                                     ["yours", "yours, from the editor below"]], "chapter");
    var controls = element("div", { "class": "lab-controls" }, [
      labelled("chapter", chapter), labelled("max depth", depth), labelled("ε", epsilon),
      labelled("rays per pixel", spp), labelled("size", size), labelled("shader", which)]);
    var gpuCanvas = element("canvas", { id: "lab-gpu", "class": "lab-image" });
    var cpuCanvas = element("canvas", { id: "lab-cpu", "class": "lab-image" });
    var diffCanvas = element("canvas", { id: "lab-difference", "class": "lab-image" });
    var frame = element("p", { id: "lab-frame", "class": "lab-frame", text: "…" });
    var agreement = element("p", { id: "lab-agreement", "class": "lab-agreement" });
    var cpuCaption = element("figcaption");
    box.appendChild(controls);
    box.appendChild(element("div", { "class": "lab-figures" }, [
      figure("WebGPU: the shader in this page", gpuCanvas),
      element("figure", { "class": "lab-figure" }, [cpuCanvas, cpuCaption]),
      figure("the difference (red: the GPU's brighter, blue: darker)", diffCanvas)]));
    box.appendChild(frame);
    box.appendChild(agreement);

    function current() {
      return LAB.chapters[Number(chapter.value) - 1];
    }
    chapter.addEventListener("change", function () {
      // As `--like` does: the chapter's own depth and rays.
      depth.value = String(current().maxDepth);
      spp.value = String(current().spp);
      update();
    });
    [depth, epsilon, spp, size, which].forEach(function (c) { c.addEventListener("change", update); });
    depth.value = String(current().maxDepth);

    var pending = false;
    function update() {
      if (pending) return;
      pending = true;
      box.dataset.state = "rendering";
      onGpu(function () {
        pending = false;
        return once();
      });
    }

    function once() {
      var c = current(), wh = size.value.split("x").map(Number);
      var maxDepth = Math.max(1, Math.min(64, Math.round(Number(depth.value)) || 1));
      var settings = { width: wh[0], height: wh[1], maxDepth: maxDepth, epsilon: Number(epsilon.value),
                       spp: Number(spp.value), features: c.features, scene: "lab" };
      var text = which.value === "yours" ? editorText() : LAB.shader;
      var reference = references[c.number - 1];
      draw(cpuCanvas, reference);
      cpuCaption.textContent = "the CPU: " + c.binary + "'s own render, " + reference.width + " × " +
        reference.height + ", its defaults";
      return compile(text, maxDepth).then(function (tracer) {
        if (tracer.errors) {
          frame.textContent = "The shader does not compile: " + place(tracer.errors[0]);
          box.dataset.state = "error";
          return;
        }
        return renderFrame(tracer, settings).then(function (image) {
          draw(gpuCanvas, image);
          frame.textContent = "Frame: " + image.frameMs.toFixed(0) + " ms (" + image.width + " × " +
            image.height + ", " + thousands(image.rays) + " rays, " + image.dispatches + " dispatch" +
            (image.dispatches > 1 ? "es" : "") + ", " + (image.rays / image.frameMs / 1e3).toFixed(1) +
            " Mrays/s) on " + gpu.adapter + ".";
          box.dataset.frameMs = image.frameMs.toFixed(1);
          box.dataset.size = image.width + "x" + image.height;
          box.dataset.chapter = String(c.number);
          var comparable = image.width === reference.width && image.height === reference.height &&
            maxDepth === c.maxDepth && settings.spp === c.spp && settings.epsilon === 1e-4;
          if (!comparable) {
            var ctx = diffCanvas.getContext("2d");
            ctx.clearRect(0, 0, diffCanvas.width, diffCanvas.height);
            agreement.textContent = "Not compared: the CPU render is chapter " + c.number + " at " +
              reference.width + " × " + reference.height + ", max depth " + c.maxDepth + ", " + c.spp +
              " ray" + (c.spp > 1 ? "s" : "") + " per pixel and ε 1e-4; set those to compare.";
            delete box.dataset.within;
            box.dataset.passes = "";
          } else {
            var a = compare(image, reference);
            draw(diffCanvas, difference(image, reference));
            agreement.textContent = (a.passes ? "✓ " : "✗ ") + "Against " + c.binary + " on the CPU: " +
              agreementText(a) + (a.passes ? ": within the lab model's tolerance." :
              ": outside the lab model's tolerance.");
            box.dataset.within = String(a.within);
            box.dataset.mean = String(a.mean);
            box.dataset.passes = a.passes ? "yes" : "no";
          }
          box.dataset.state = "done";
        });
      }).catch(function (error) {
        frame.textContent = "The render failed: " + error.message;
        box.dataset.state = "error";
      });
    }
    return update;
  }

  function place(error) {
    return LAB.shaderName + ":" + error.line + ":" + error.column + ": " + error.message;
  }

  // The editor: a textarea with line numbers, the learner's text kept in
  // the browser's storage.
  function editor(box) {
    var saved = null;
    try { saved = window.localStorage.getItem(STORE); } catch (e) { saved = null; }
    var gutter = element("pre", { "class": "lab-gutter", "aria-hidden": "true" });
    var area = element("textarea", { id: "lab-editor", "class": "lab-editor", spellcheck: "false",
                                     wrap: "off", "aria-label": "your tracer.wgsl" });
    area.value = saved === null ? LAB.blank : saved;
    function numbers() {
      var n = area.value.split("\n").length, text = "";
      for (var i = 1; i <= n; i++) text += i + "\n";
      gutter.textContent = text;
      gutter.scrollTop = area.scrollTop;
    }
    area.addEventListener("scroll", function () { gutter.scrollTop = area.scrollTop; });
    numbers();
    var restore = element("button", { id: "lab-restore", type: "button", text: "Restore the blank" });
    var armed = false;
    restore.addEventListener("click", function () {
      // Two clicks: one click alone never throws a learner's work away.
      if (!armed && area.value !== LAB.blank) {
        armed = true;
        restore.textContent = "Click again: your text is replaced by the blank";
        setTimeout(function () { armed = false; restore.textContent = "Restore the blank"; }, 4000);
        return;
      }
      armed = false;
      restore.textContent = "Restore the blank";
      area.value = LAB.blank;
      area.dispatchEvent(new Event("input"));
    });
    box.appendChild(element("div", { "class": "lab-edit" }, [gutter, area]));
    box.appendChild(element("p", {}, [restore]));
    return { area: area, numbers: numbers };
  }

  // Move the caret to a line and column of the editor.
  function goTo(area, line, column) {
    var lines = area.value.split("\n"), at = 0;
    for (var i = 0; i < line - 1 && i < lines.length; i++) at += lines[i].length + 1;
    at += Math.max(0, column - 1);
    area.focus();
    area.setSelectionRange(at, at);
    var height = area.scrollHeight / Math.max(1, lines.length);
    area.scrollTop = Math.max(0, (line - 5) * height);
  }

  // The tasks: on every edit, compile, render each stage of `learn check
  // shader` and judge it against that chapter's CPU render.
  function tasks(box, stageReferences, edit) {
    var verdict = element("p", { id: "lab-verdict", "class": "lab-verdict", text: "…" });
    var messages = element("ul", { id: "lab-messages", "class": "lab-messages" });
    var list = element("ol", { id: "lab-stages", "class": "lab-stages" });
    var rows = LAB.stages.map(function (s) {
      var row = element("li", { text: "· " + s.label + ": " + s.task });
      list.appendChild(row);
      return row;
    });
    var yours = element("canvas", { id: "lab-yours", "class": "lab-image lab-small" });
    var theirs = element("canvas", { id: "lab-reference", "class": "lab-image lab-small" });
    var diff = element("canvas", { id: "lab-task-difference", "class": "lab-image lab-small" });
    var refCaption = element("figcaption");
    var pictures = element("div", { "class": "lab-figures", hidden: "" }, [
      figure("yours", yours),
      element("figure", { "class": "lab-figure" }, [theirs, refCaption]),
      figure("the difference (red: yours brighter, blue: darker)", diff)]);
    box.appendChild(verdict);
    box.appendChild(messages);
    box.appendChild(list);
    box.appendChild(pictures);

    var generation = 0;
    function check() {
      var mine = ++generation, text = edit.area.value, began = performance.now();
      var took = function () { box.dataset.ms = (performance.now() - began).toFixed(0); };
      box.dataset.state = "checking";
      verdict.textContent = "Checking …";
      var stale = function () { return mine !== generation; };
      return onGpu(function () {
        if (stale()) return;
        // One compile for the four pictures, its stack sized for the
        // deepest: a stack deeper than a render needs leaves its picture
        // as it is, and chapter 10 renders a shallower depth on it too.
        var deepest = Math.max.apply(null, LAB.stages.map(function (s) { return s.maxDepth; }));
        return compile(text, deepest).then(function (tracer) {
          if (stale()) return;
          messages.textContent = "";
          var errors = tracer.errors ? [tracer] : [];
          if (errors.length) {
            pictures.hidden = true;
            rows.forEach(function (row, i) { row.textContent = "· " + LAB.stages[i].label + ": " + LAB.stages[i].task; });
            verdict.textContent = "✗ It does not compile:";
            errors[0].errors.forEach(function (e) {
              var link = element("a", { href: "#lab-editor", text: place(e) });
              link.addEventListener("click", function (event) { event.preventDefault(); goTo(edit.area, e.line, e.column); });
              messages.appendChild(element("li", {}, [link]));
            });
            took();
            box.dataset.state = "compile-error";
            box.dataset.line = String(errors[0].errors[0].line);
            box.dataset.column = String(errors[0].errors[0].column);
            box.dataset.stage = "";
            return;
          }
          return stage(0, tracer);
        });
      }).catch(function (error) {
        verdict.textContent = "The check failed: " + error.message;
        box.dataset.state = "error";
      });

      function stage(i, tracer) {
        if (stale()) return;
        if (i === LAB.stages.length) {
          pictures.hidden = true;
          verdict.textContent = "✓ Done: the shader passes all " + LAB.stages.length +
            " pictures, as `cargo run -p learn -- check shader` would pass it.";
          took();
          box.dataset.state = "passed";
          box.dataset.stage = "";
          return;
        }
        var s = LAB.stages[i];
        var settings = { width: LAB.check.width, height: LAB.check.height, maxDepth: s.maxDepth,
                         epsilon: 1e-4, spp: s.spp, features: s.features, scene: s.scene };
        return renderFrame(tracer, settings).then(function (image) {
          if (stale()) return;
          var reference = stageReferences[i], a = compare(image, reference);
          if (a.passes) {
            rows[i].textContent = "✓ " + s.label + ": the render matches chapter " + s.chapter +
              "'s within the lab model's tolerance: " + s.task + " is right";
            return stage(i + 1, tracer);
          }
          for (var k = i; k < rows.length; k++) {
            rows[k].textContent = (k === i ? "✗ " : "· ") + LAB.stages[k].label + ": " + LAB.stages[k].task;
          }
          verdict.textContent = "";
          verdict.appendChild(element("span", { text: "✗ " + s.label + ", the render differs from chapter " +
            s.chapter + "'s, which adds " + s.shows + ": " + s.task + " (" }));
          verdict.appendChild(element("code", { text: s.region }));
          verdict.appendChild(element("span", { text: ") is not right yet." }));
          verdict.appendChild(element("span", { "class": "lab-numbers", text: " " + agreementText(a) + "." }));
          draw(yours, image);
          draw(theirs, reference);
          draw(diff, difference(image, reference));
          refCaption.textContent = s.package + "'s own render on the CPU";
          pictures.hidden = false;
          took();
          box.dataset.state = "failed";
          box.dataset.stage = String(i);
          box.dataset.region = s.region;
        });
      }
    }

    var timer = null;
    edit.area.addEventListener("input", function () {
      edit.numbers();
      try { window.localStorage.setItem(STORE, edit.area.value); } catch (e) { /* private mode */ }
      box.dataset.state = "editing";
      clearTimeout(timer);
      timer = setTimeout(check, 400);
    });
    return check;
  }

  function start() {
    var root = document.getElementById("lab-page");
    if (!root) return;
    LAB = window.RAYLAB_LAB;
    statusLine = document.getElementById("lab-status");
    if (!LAB) {
      say("The page's data (figures/lab-in-browser/lab-data.js) is missing: run the main job.");
      return;
    }
    var tasksBox = document.getElementById("lab-tasks");
    var edit = editor(tasksBox);
    openGpu().then(function () {
      root.dataset.gpu = "ready";
      say("WebGPU is here (" + gpu.adapter + "): the pictures below are rendered in this page by " +
          "chapter 10's tracer.wgsl.");
      return Promise.all(LAB.chapters.map(function (c) { return decodePng(c.png); }).concat(
        LAB.stages.map(function (s) { return decodePng(s.png); })));
    }, function (why) {
      root.dataset.gpu = "none";
      say("This browser gives the page no WebGPU (" + why.message + "): the chapters' CPU renders " +
          "are below, and the tasks cannot be checked here.");
      throw null;
    }).then(function (images) {
      var chapterImages = images.slice(0, LAB.chapters.length);
      var stageImages = images.slice(LAB.chapters.length);
      var update = viewer(document.getElementById("lab-viewer"), chapterImages,
                          function () { return edit.area.value; });
      var check = tasks(tasksBox, stageImages, edit);
      update();
      check();
    }).catch(function (error) {
      if (error) say("The page could not start: " + error.message);
    });
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
