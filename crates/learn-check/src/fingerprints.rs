//! Learning what each catalogued mistake looks like to the check: the
//! mistake made in the reference's region, laid out in a lab of its own
//! ([`learn::mistakes::mistake_lab`], never the learner's crate), built and
//! checked there once, and what the check saw kept as its fingerprint,
//! with a key made from the wrong source (a chapter that changes is learnt
//! again).

use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::io::Write;
use std::path::{Path, PathBuf};

use learn::lab::Lab;
use learn::mistakes::{Fingerprint, Mistake, made_in, mistake_lab, of, source_file};
use learn::path::Item;

use crate::verdict::Verdict;
use learn::limits::Limits;

const LIMITS: Limits = Limits {
    tests: std::time::Duration::from_secs(20),
    render: std::time::Duration::from_secs(30),
};

/// The fingerprints of every mistake of the exercise `item`, from the
/// cache or learnt now (saying so first: it builds the exercise).
pub fn fingerprints(lab: &Lab, item: Item, out: &mut dyn Write) -> Vec<(Mistake, Fingerprint)> {
    let name = item.name();
    let mistakes: Vec<&Mistake> = of(&name).collect();
    if mistakes.is_empty() {
        return Vec::new();
    }
    let cache = mistake_lab(lab);
    let dir = cache.dir.join("fingerprints");
    let mut known = Vec::new();
    let mut to_learn = Vec::new();
    for mistake in mistakes {
        let Some(file) = source_file(&lab.root, mistake) else {
            continue;
        };
        let Some(wrong) = std::fs::read_to_string(lab.root.join(&file))
            .ok()
            .and_then(|text| made_in(&text, mistake))
        else {
            continue;
        };
        let key = key_of(&wrong, mistake);
        let path = dir.join(format!("{}-{}.toml", mistake.exercise, mistake.slug));
        let cached: Option<Fingerprint> = std::fs::read_to_string(&path)
            .ok()
            .and_then(|text| toml::from_str(&text).ok());
        match cached {
            Some(print) if print.key == key => known.push((*mistake, print)),
            _ => to_learn.push((*mistake, file, wrong, key, path)),
        }
    }
    if !to_learn.is_empty() {
        let _ = writeln!(
            out,
            "  learning what {} known mistake{} of `{name}` look like, once (each built and checked \
             in {}; a few seconds each after the first build) …",
            to_learn.len(),
            if to_learn.len() == 1 { "" } else { "s" },
            learn::run::shown(&cache.dir, &lab.root),
        );
        let _ = out.flush();
    }
    for (mistake, file, wrong, key, path) in to_learn {
        let mut print = learn_one(&cache, item, &file, &wrong);
        print.key = key;
        if let Some(image) = &print.image {
            let keep = path.with_extension("png");
            if std::fs::create_dir_all(&dir).is_ok() && std::fs::copy(image, &keep).is_ok() {
                print.image = Some(keep);
            } else {
                print.image = None;
            }
        }
        if let Ok(text) = toml::to_string(&print) {
            let _ = std::fs::create_dir_all(&dir);
            let _ = std::fs::write(&path, text);
        }
        known.push((mistake, print));
    }
    known
}

fn key_of(wrong: &str, mistake: &Mistake) -> String {
    let mut hasher = DefaultHasher::new();
    (wrong, mistake.slug, env!("CARGO_PKG_VERSION")).hash(&mut hasher);
    format!("{:016x}", hasher.finish())
}

/// Build and check one mistake in the mistake lab.
fn learn_one(cache: &Lab, item: Item, file: &Path, wrong: &str) -> Fingerprint {
    let mut quiet = Vec::new();
    let (verdict, picture_dir) = match item {
        Item::Core(core) => {
            let src = cache.core_src();
            let _ = std::fs::remove_dir_all(&src);
            let _ = std::fs::remove_file(cache.progress_path());
            for exercise in &learn::core::CORE_EXERCISES {
                let _ = cache.start_core(exercise, true);
                let _ = cache.record_core_pass(exercise.name);
            }
            let name = file.file_name().unwrap_or_default();
            let _ = std::fs::write(src.join(name), wrong);
            let verdict = crate::core_stages::check_core_quietly(cache, core, LIMITS, &mut quiet);
            (verdict, cache.core_check_dir(core))
        }
        Item::Chapter(chapter) => {
            let folder = cache.folder(chapter);
            let _ = std::fs::remove_dir_all(&folder);
            let _ = cache.start(chapter, true);
            if let Ok(solved) = learn::exercise::blank_only(wrong, |_| false) {
                let _ = std::fs::write(folder.join(chapter.step), solved.exercise);
            }
            let verdict = crate::chapter_stages::check_quietly(cache, chapter, LIMITS, &mut quiet);
            if let Verdict::TestsFail {
                failing, messages, ..
            } = &verdict
            {
                // Its picture too, to tell apart mistakes that fail the
                // same tests.
                let image = folder.join("check/learner.png");
                let _ = std::fs::remove_file(&image);
                let picture =
                    crate::chapter_stages::check_picture_with(cache, chapter, LIMITS, &mut quiet);
                return Fingerprint {
                    verdict: format!("{verdict:?}").chars().take(120).collect(),
                    failing: failing.clone(),
                    messages: messages.clone(),
                    image: (matches!(picture, Verdict::Differs(_)) && image.is_file())
                        .then_some(image),
                    picture_passes: picture.passed(),
                    ..Fingerprint::default()
                };
            }
            (verdict, folder.join("check"))
        }
        Item::Shader => (Verdict::NoExercise, PathBuf::new()),
    };
    let mut print = Fingerprint {
        verdict: format!("{verdict:?}").chars().take(120).collect(),
        ..Fingerprint::default()
    };
    match verdict {
        Verdict::TestsFail {
            failing, messages, ..
        } => {
            print.failing = failing;
            print.messages = messages;
        }
        Verdict::Differs(_) => print.image = Some(picture_dir.join("learner.png")),
        _ => {}
    }
    print
}
