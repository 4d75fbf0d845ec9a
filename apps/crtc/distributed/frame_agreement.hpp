// Every rank evaluates the frame itself (no scene is sent over the network), then the ranks
// check that they built the same one before any of them renders it; an animation shared by
// frames checks the script once instead.
#pragma once

#include "captured_errors.hpp"
#include "mpi_session.hpp"
#include "render_command.hpp"

namespace crt::crtc::distributed {

/// Evaluates `frame` into `c` on this rank; every rank calls it for the same frame. Returns
/// whether every rank evaluated it without errors, from the same inputs (frame_hash.hpp: the
/// script's files, the options, the images and meshes it reads). Rank 0 says why not: the
/// messages of a rank that failed (`captured`, its standard error, is sent to rank 0) or
/// that the ranks differ.
bool evaluateOnEveryRank(MpiSession& session, const Options& options,
                         const CompileFrame& compileFrame, int frame, lang::Compilation& c,
                         CapturedErrors* captured);

/// Whether every rank has the same crtc and the same script (its path and text): the check an
/// animation shared by frames can make before any rank evaluates one. Rank 0 says why not.
bool sameScriptOnEveryRank(MpiSession& session, const Options& options);

/// Evaluates `frame` into `c` on this process, rank `rank`; false, with the reason in `why` unless
/// the diagnostics printed say it, if it fails (kTestFailRankVariable makes it fail).
bool evaluateOnThisRank(int rank, const CompileFrame& compileFrame, int frame,
                        lang::Compilation& c, std::string& why);

/// The environment variable that makes one rank's evaluation fail, for crtc's tests.
inline constexpr const char* kTestFailRankVariable = "CRT_TEST_FAIL_RANK";

} // namespace crt::crtc::distributed
