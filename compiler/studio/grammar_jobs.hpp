#pragma once
// The studio's compiles and runs, one at a time on one worker thread. A new
// run cancels the one in flight (and any still waiting): a page that sends
// a run per edit never waits for a picture it no longer shows.
#include <atomic>
#include <cstdint>
#include <string>

#include "studio/api_reply.hpp"
#include "studio/example_inference.hpp"
#include "studio/grammar_derive.hpp"
#include "studio/image_shelf.hpp"
#include "studio/job_thread.hpp"

namespace g2d::studio {

class GrammarJobs {
public:
    explicit GrammarJobs(std::string path) : path_(std::move(path)) {}
    ~GrammarJobs();   // cancels the run in flight

    // Each blocks the calling (HTTP) thread until the worker has answered.
    ApiReply check(const std::string& text);
    ApiReply complete(const std::string& text, std::uint32_t line, std::uint32_t character);
    ApiReply run(const RunInput& input);
    ApiReply exportFile(const RunInput& input, ExportFormat format);
    ApiReply seeds(const RunInput& input, std::uint64_t first, int count, int width);
    ApiReply imports();
    // Infer mode: a run like any other, so a newer run or inference cancels it.
    ApiReply infer(const InferInput& input);

    void cancelRuns();

    // The image files the runs' SVGs link, served at their addresses.
    const ImageShelf& images() const { return images_; }

private:
    // Runs `job` as the newest run: a newer one cancels it.
    ApiReply newestRun(std::function<ApiReply(const std::function<bool()>& cancelled)> job);
    ApiReply onWorker(std::function<ApiReply()> job);

    std::string path_;
    ImageShelf images_;
    std::atomic<std::uint64_t> latestRun_{0};
    JobThread worker_;   // last: joined first, while the rest still exists
};

}  // namespace g2d::studio
