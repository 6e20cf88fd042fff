//! The page "The lab in your browser" in a real browser: headless Chromium
//! (Debian's, with WebGPU on its software rasteriser, SwiftShader) loads
//! the built page from disk and from a local server, renders chapters 1–5
//! with chapter 10's shader, and judges the lab's three tasks.
//!
//! It needs `chromium`, `node` and `tests/browser/node_modules` (`npm ci`
//! in `tests/browser/`); `.ci/run` installs them. Without them it says so
//! and passes, unless `CI` is set: there it fails. `RAYLAB_LAB_PAGE_DIR=DIR`
//! keeps the built page in DIR, with screenshots of it and of each
//! answer's verdict, to look at.

use std::path::{Path, PathBuf};
use std::process::Command;

use ch10_gpu::shader::{self, ShaderError, Source};
use serde_json::{Value, json};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// What the test needs on this machine, or why it cannot run.
fn tools() -> Result<(PathBuf, PathBuf), String> {
    let chromium = std::env::var_os("CHROMIUM")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/usr/bin/chromium"));
    if !chromium.is_file() {
        return Err(format!("no Chromium at {}", chromium.display()));
    }
    let node = Command::new("node").arg("--version").output();
    if !node.is_ok_and(|o| o.status.success()) {
        return Err("no `node` on the PATH".into());
    }
    let driver = root().join("tests/browser");
    if !driver.join("node_modules/playwright-core").is_dir() {
        return Err(format!(
            "no playwright-core in {}: run `npm ci` there",
            driver.display()
        ));
    }
    Ok((chromium, driver))
}

/// A book of one page, this page, built as the main job builds the book.
fn build_page(dir: &Path) -> PathBuf {
    let book = dir.join("book");
    let src = book.join("src");
    std::fs::create_dir_all(&src).unwrap();
    let real = root().join("book");
    for file in workbook::book::BOOK_FILES {
        std::fs::copy(real.join(file), book.join(file)).unwrap();
    }
    std::fs::copy(
        real.join("src/lab-in-browser.md"),
        src.join("lab-in-browser.md"),
    )
    .unwrap();
    std::fs::write(
        src.join("SUMMARY.md"),
        "# Summary\n\n- [The lab in your browser](lab-in-browser.md)\n",
    )
    .unwrap();
    workbook::lab_page::make_lab_page(&src.join("figures/lab-in-browser"), &root().join("scenes"))
        .unwrap();
    let index = workbook::book::build(&book).unwrap();
    index.parent().unwrap().to_owned()
}

/// The reference shader with `from` written as `to`.
fn edited(solution: &str, from: &str, to: &str) -> String {
    assert!(solution.contains(from), "the shader has `{from}`");
    solution.replacen(from, to, 1)
}

/// The blank with its three TODO lines answered in the learner's own
/// words, not the reference's.
fn answered_differently(blank: &str) -> String {
    let answers = [
        (
            "shadow_feeler",
            "        let start = hit.point + params.epsilon * params.to_sun;\n\
             \x20       count(work, SHADOW);\n\
             \x20       work.rays = work.rays + 1u;\n\
             \x20       k = select(SUN_LIT, SUN_IN_SHADOW, any_hit(start, params.to_sun));\n",
        ),
        (
            "reflection",
            "        let n = hit.facing_normal;\n\
             \x20       let m = normalize(ray.direction - 2.0 * dot(ray.direction, n) * n);\n\
             \x20       kept = kept - r;\n\
             \x20       reflected = Pending(hit.point + params.epsilon * m, m, r, 0u, REFLECTED);\n",
        ),
        (
            "refraction",
            "        var eta = hit.ior;\n\
             \x20       if hit.entering {\n\
             \x20           eta = 1.0 / hit.ior;\n\
             \x20       }\n\
             \x20       let bent = refract(ray.direction, hit.facing_normal, eta);\n\
             \x20       var d = normalize(reflect(ray.direction, hit.facing_normal));\n\
             \x20       var kind = TOTAL_INTERNAL;\n\
             \x20       if dot(bent, bent) > 0.0 {\n\
             \x20           d = normalize(bent);\n\
             \x20           kind = REFRACTED;\n\
             \x20       }\n\
             \x20       transmitted = Pending(hit.point + params.epsilon * d, d, t, 0u, kind);\n\
             \x20       kept = kept - t;\n",
        ),
    ];
    let blanked = learn::shader::blank_shader(shader::BUILT_IN).unwrap();
    let mut text = blank.to_owned();
    for (region, answer) in answers {
        let task = blanked
            .tasks
            .iter()
            .find(|t| t.name == region)
            .unwrap_or_else(|| panic!("no task {region}"));
        let todo = format!("        // TODO: {}\n", task.text);
        assert!(text.contains(&todo), "the blank has the TODO of {region}");
        text = text.replacen(&todo, answer, 1);
    }
    text
}

#[test]
fn the_lab_page_renders_every_chapter_and_judges_the_three_tasks_in_a_browser() {
    let (chromium, driver) = match tools() {
        Ok(found) => found,
        Err(why) if std::env::var_os("CI").is_none() => {
            eprintln!(
                "this test needs Chromium, node and playwright-core, so it checked nothing: {why}"
            );
            return;
        }
        Err(why) => panic!("CI runs the browser test, and {why}"),
    };
    let kept_dir = std::env::var_os("RAYLAB_LAB_PAGE_DIR").map(PathBuf::from);
    let temp = tempfile::tempdir().unwrap();
    let dir = kept_dir.clone().unwrap_or_else(|| temp.path().to_owned());
    let build = build_page(&dir);
    let page = build.join("lab-in-browser.html");
    assert!(page.is_file(), "{}", page.display());

    let blanked = learn::shader::blank_shader(shader::BUILT_IN).unwrap();
    let (blank, solution) = (&blanked.exercise, &blanked.solution);
    // The wrong answers of the learner trial (issue 32's note), each with
    // the stage that must catch it: 0 the feeler (chapter 2), 1 the
    // reflection push (chapter 3), 2 the refraction push (chapter 4), 3
    // past the critical angle (chapter 4 under water).
    let wrong = [
        (
            "feeler started on the surface (shadow acne)",
            "let feeler = hit.point + params.to_sun * params.epsilon;",
            "let feeler = hit.point;",
            0,
        ),
        (
            "feeler sent away from the sun",
            "if any_hit(feeler, params.to_sun) {",
            "if any_hit(feeler, -params.to_sun) {",
            0,
        ),
        (
            "reflection started on the surface",
            "reflected = Pending(hit.point + d * params.epsilon, d, r, 0u, REFLECTED);",
            "reflected = Pending(hit.point, d, r, 0u, REFLECTED);",
            1,
        ),
        (
            "mirror share not taken off the local light",
            "        kept -= r;\n",
            "",
            1,
        ),
        (
            "index ratio inverted",
            "let eta = select(hit.ior, 1.0 / hit.ior, hit.entering);",
            "let eta = select(1.0 / hit.ior, hit.ior, hit.entering);",
            2,
        ),
        (
            "refracted share weighted by its parent twice",
            "transmitted = Pending(hit.point + d * params.epsilon, d, t, 0u, REFRACTED);",
            "transmitted = Pending(hit.point + d * params.epsilon, d, t * ray.weight, 0u, REFRACTED);",
            2,
        ),
        (
            "glass share not taken off the local light",
            "        kept -= t;\n",
            "",
            2,
        ),
        (
            "glass that always refracts",
            "if all(bent == vec3<f32>(0.0)) {",
            "if false {",
            3,
        ),
    ];
    let typo = edited(solution, "k = SUN_IN_SHADOW;", "k = SUN_IN_SHADOW + foo;");
    // Where naga, the compiler of `cargo run -p learn -- check shader`,
    // places it.
    let Err(ShaderError::At { line, column, .. }) = shader::check(&Source {
        name: "tracer.wgsl".into(),
        text: typo.clone(),
    }) else {
        panic!("naga places the typo");
    };

    let mut variants = vec![
        json!({ "name": "the blank", "text": blank, "expect": "failed", "stage": 0 }),
        json!({ "name": "the reference", "text": solution, "expect": "passed" }),
        json!({ "name": "answered differently", "text": answered_differently(blank),
                "expect": "passed" }),
        json!({ "name": "a typo", "text": typo, "expect": "compile-error",
                "line": line, "column": column }),
    ];
    for (name, from, to, stage) in wrong {
        variants.push(json!({ "name": name, "text": edited(solution, from, to),
                              "expect": "failed", "stage": stage }));
    }
    let kept = edited(solution, "// Chapter 2: a feeler", "// My feeler");
    let cases = json!({
        "chromium": chromium,
        "page": format!("file://{}", page.display()),
        "root": build,
        "pagePath": "lab-in-browser.html",
        "chapters": [1, 2, 3, 4, 5],
        "size": "320x240",
        "variants": variants,
        "kept": kept,
        "shots": kept_dir,
        "timeSizes": std::env::var("RAYLAB_LAB_PAGE_TIMES").ok().map(|_| ["320x240", "800x600"]),
        "timeChapters": [1, 2, 3, 4, 5],
    });
    let cases_file = dir.join("cases.json");
    std::fs::write(&cases_file, cases.to_string()).unwrap();
    let output = Command::new("node")
        .arg(driver.join("lab_in_browser.js"))
        .arg(&cases_file)
        .current_dir(&driver)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "node failed:\n{stdout}\n{stderr}");
    let result: Value = serde_json::from_str(stdout.trim())
        .unwrap_or_else(|e| panic!("the driver's output ({e}):\n{stdout}\n{stderr}"));
    println!("phases (ms): {}", result["phases"]);
    for t in result["times"].as_array().into_iter().flatten() {
        println!(
            "frame time: chapter {} at {}: {} ms",
            t["chapter"], t["size"], t["frameMs"]
        );
    }
    assert!(result["error"].is_null(), "{}", result["error"]);
    assert_eq!(result["gpu"], "ready", "{}", result["status"]);
    assert_eq!(result["console"], json!([]), "errors in the page's console");

    for view in result["chapters"].as_array().unwrap() {
        println!(
            "chapter {}: {} {}",
            view["chapter"], view["frame"], view["agreement"]
        );
        assert_eq!(view["state"], "done", "{view}");
        assert_eq!(view["size"], "320x240", "{view}");
        assert_eq!(view["passes"], "yes", "{view}");
    }
    assert_eq!(result["chapters"].as_array().unwrap().len(), 5);

    assert_eq!(result["first"]["state"], "failed", "{}", result["first"]);
    let judged = result["variants"].as_array().unwrap();
    assert_eq!(judged.len(), variants.len());
    for (asked, got) in variants.iter().zip(judged) {
        println!("{} ({} ms): {}", asked["name"], got["ms"], got["verdict"]);
        assert_eq!(got["state"], asked["expect"], "{}: {got}", asked["name"]);
        if let Some(stage) = asked["stage"].as_u64() {
            assert_eq!(got["stage"], stage.to_string(), "{}: {got}", asked["name"]);
        }
        if asked["expect"] == "compile-error" {
            let place = (got["line"].as_str(), got["column"].as_str());
            let naga = (line.to_string(), column.to_string());
            assert_eq!(
                place,
                (Some(naga.0.as_str()), Some(naga.1.as_str())),
                "{got}"
            );
            let shown = format!("tracer.wgsl:{line}:{column}: ");
            assert!(got["messages"].as_str().unwrap().contains(&shown), "{got}");
        }
    }
    assert_eq!(
        result["keptAfterReload"], true,
        "the learner's text survives a reload"
    );

    assert_eq!(result["served"]["gpu"], "ready", "{}", result["served"]);
    assert_eq!(
        result["served"]["view"]["passes"], "yes",
        "{}",
        result["served"]
    );
    let base = result["served"]["base"].as_str().unwrap();
    let requests = result["requests"].as_array().unwrap();
    assert!(requests.len() > 5, "{requests:?}");
    for url in requests {
        let url = url.as_str().unwrap();
        let local = ["file://", "data:", "blob:"]
            .iter()
            .any(|s| url.starts_with(s))
            || url.starts_with(base);
        assert!(local, "the page loaded {url} from the network");
    }
}
