//! `--objects list|tree`: how a faster chapter's rays find their hits.
//!
//! Chapters 7 and 8 trace eight rays at a time and find their hits in the
//! scene's list, every sphere tested, as chapters 1–6 do. Given
//! `--objects tree` they search this chapter's tree instead, eight rays
//! against each node, and make the same bytes. The choice is made once per
//! render: the program picks its renderer from it, and nothing in the
//! trace loop asks again.

use clap::ValueEnum;

/// Where the rays look for their hits.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum Objects {
    /// Every object tested, the scene's list (chapters 1–6)
    #[default]
    List,
    /// Through chapter 9's bounding volume hierarchy: the same hits
    Tree,
}

/// The id of [`arg`] in a command's matches.
pub const ID: &str = "objects";

/// The `--objects` flag, the list when it is not given.
pub fn arg() -> clap::Arg {
    clap::Arg::new(ID)
        .long("objects")
        .value_name("OBJECTS")
        .value_parser(clap::builder::EnumValueParser::<Objects>::new())
        .default_value("list")
        .help("How each ray finds its hit: every object tested (list) or through chapter 9's tree of boxes (tree), the same image either way")
}

/// What `--objects` chose in `matches`.
pub fn chosen(matches: &clap::ArgMatches) -> Objects {
    matches.get_one::<Objects>(ID).copied().unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> Result<Objects, clap::Error> {
        let matches = clap::Command::new("ch07")
            .arg(arg())
            .try_get_matches_from(args)?;
        Ok(chosen(&matches))
    }

    #[test]
    fn objects_are_the_list_unless_the_tree_is_asked_for() {
        assert_eq!(parse(&["ch07"]).unwrap(), Objects::List);
        assert_eq!(
            parse(&["ch07", "--objects", "tree"]).unwrap(),
            Objects::Tree
        );
        assert_eq!(parse(&["ch07", "--objects=list"]).unwrap(), Objects::List);
    }

    #[test]
    fn an_unknown_kind_of_objects_is_an_error_that_lists_both() {
        let err = parse(&["ch07", "--objects", "grid"])
            .unwrap_err()
            .to_string();
        assert!(err.contains("list") && err.contains("tree"), "{err}");
    }
}
