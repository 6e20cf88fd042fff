//! `--like chNN-…`: which of chapters 1–5 chapter 9 traces as (chapter
//! 7's [`Like`], with this chapter's name in its messages).

use std::ffi::OsString;

pub use ch07_eight_rays::like::Like;

/// Take `--like NAME` (or `--like=NAME`) out of the arguments; chapter 5
/// when absent. The rest go to the shared command line.
pub fn take_like(args: Vec<OsString>) -> Result<(Like, Vec<OsString>), String> {
    ch07_eight_rays::like::take_like(args)
        .map_err(|message| message.replace("that chapter 7 can", "that chapter 9 can"))
}
