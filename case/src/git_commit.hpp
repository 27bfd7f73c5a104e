#pragma once
// The source commit the program was built from, "<commit>-modified" for a tree with uncommitted
// changes, or "unknown" outside a git checkout (generated at build time: cmake/git_commit.cmake).
namespace hm::cases {
extern const char* const kGitCommit;
}
