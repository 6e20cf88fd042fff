// The book's two interactive figures, in plain JavaScript (no library, no
// network): an image comparison slider and a stepper over a sequence.
//
//   <div class="compare" data-before="depth 1" data-after="depth 6">
//     <img src="a.png" alt="…"> <img src="b.png" alt="…">
//   </div>
//   <div class="stepper" data-label="max depth"> <img …> <img …> … </div>
//
// Without JavaScript both show their images one after the other.
(function () {
  "use strict";

  function compare(box) {
    var images = box.querySelectorAll("img");
    if (images.length !== 2) return;
    box.classList.add("compare-live");
    // The first image sets the size; the second lies exactly over it and
    // shows only right of the handle.
    var frame = document.createElement("div");
    frame.className = "compare-frame";
    box.insertBefore(frame, images[0]);
    frame.appendChild(images[0]);
    var over = document.createElement("div");
    over.className = "compare-over";
    over.appendChild(images[1]);
    frame.appendChild(over);
    var handle = document.createElement("div");
    handle.className = "compare-handle";
    frame.appendChild(handle);
    var labels = document.createElement("div");
    labels.className = "compare-labels";
    var before = document.createElement("span");
    before.textContent = "◀ " + (box.dataset.before || "");
    var after = document.createElement("span");
    after.textContent = (box.dataset.after || "") + " ▶";
    labels.appendChild(before);
    labels.appendChild(after);
    box.appendChild(labels);
    var range = document.createElement("input");
    range.type = "range";
    range.min = "0";
    range.max = "1000";
    range.setAttribute("aria-label", "drag to compare " + before.textContent + " with " + after.textContent);
    box.appendChild(range);
    function set(fraction) {
      var percent = Math.max(0, Math.min(100, fraction * 100));
      over.style.clipPath = "inset(0 0 0 " + percent + "%)";
      handle.style.left = percent + "%";
      range.value = String(Math.round(percent * 10));
    }
    range.addEventListener("input", function () { set(range.value / 1000); });
    function fromPointer(event) {
      var rect = frame.getBoundingClientRect();
      set((event.clientX - rect.left) / rect.width);
    }
    var dragging = false;
    frame.addEventListener("pointerdown", function (e) { dragging = true; fromPointer(e); e.preventDefault(); });
    window.addEventListener("pointermove", function (e) { if (dragging) fromPointer(e); });
    window.addEventListener("pointerup", function () { dragging = false; });
    set(0.5);
  }

  function stepper(box) {
    var images = Array.prototype.slice.call(box.querySelectorAll("img"));
    if (images.length < 2) return;
    box.classList.add("stepper-live");
    var bar = document.createElement("div");
    bar.className = "stepper-bar";
    var back = document.createElement("button");
    back.textContent = "◀";
    back.setAttribute("aria-label", "previous");
    var next = document.createElement("button");
    next.textContent = "▶";
    next.setAttribute("aria-label", "next");
    var range = document.createElement("input");
    range.type = "range";
    range.min = "0";
    range.max = String(images.length - 1);
    range.value = "0";
    var caption = document.createElement("span");
    caption.className = "stepper-caption";
    bar.appendChild(back);
    bar.appendChild(range);
    bar.appendChild(next);
    bar.appendChild(caption);
    box.appendChild(bar);
    function show(i) {
      i = Math.max(0, Math.min(images.length - 1, i));
      images.forEach(function (img, k) { img.style.display = k === i ? "block" : "none"; });
      range.value = String(i);
      caption.textContent = (box.dataset.label || "") + " " + (images[i].dataset.step || String(i + 1));
    }
    range.addEventListener("input", function () { show(Number(range.value)); });
    back.addEventListener("click", function () { show(Number(range.value) - 1); });
    next.addEventListener("click", function () { show(Number(range.value) + 1); });
    show(Number(box.dataset.start || 0));
  }

  function start() {
    document.querySelectorAll(".compare").forEach(compare);
    document.querySelectorAll(".stepper").forEach(stepper);
  }
  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", start);
  } else {
    start();
  }
})();
