#include "studio/grammar_jobs.hpp"

#include <future>

#include "g2d/deadline.hpp"
#include "studio/grammar_check.hpp"
#include "studio/grammar_complete.hpp"

namespace g2d::studio {

GrammarJobs::~GrammarJobs() { cancelRuns(); }

ApiReply GrammarJobs::onWorker(std::function<ApiReply()> job) {
    auto done = std::make_shared<std::promise<ApiReply>>();
    auto answer = done->get_future();
    worker_.post([job = std::move(job), done] {
        try {
            done->set_value(job());
        } catch (const std::exception& e) {   // a bug, not the grammar's fault: the server keeps running
            done->set_value(errorReply(500, std::string("internal error: ") + e.what()));
        }
    });
    return answer.get();
}

ApiReply GrammarJobs::check(const std::string& text) {
    return onWorker([this, text] { return jsonReply(200, checkText(path_, text)); });
}

ApiReply GrammarJobs::complete(const std::string& text, std::uint32_t line, std::uint32_t character) {
    return onWorker([this, text, line, character] { return jsonReply(200, completeText(path_, text, line, character)); });
}

ApiReply GrammarJobs::imports() {
    return onWorker([this] { return jsonReply(200, {{"files", importedFiles(path_)}}); });
}

ApiReply GrammarJobs::newestRun(std::function<ApiReply(const std::function<bool()>& cancelled)> job) {
    const std::uint64_t mine = ++latestRun_;
    // Inside a long step only the deadline flag is seen; between steps, the observer.
    rt::interruptDerivation();
    return onWorker([this, job = std::move(job), mine] { return job([this, mine] { return latestRun_.load() != mine; }); });
}

ApiReply GrammarJobs::run(const RunInput& input) {
    return newestRun([this, input](const auto& cancelled) { return deriveText(path_, input, cancelled, &images_); });
}

ApiReply GrammarJobs::exportFile(const RunInput& input, ExportFormat format) {
    return newestRun([this, input, format](const auto& cancelled) { return exportText(path_, input, format, cancelled); });
}

ApiReply GrammarJobs::seeds(const RunInput& input, std::uint64_t first, int count, int width) {
    return newestRun([this, input, first, count, width](const auto& cancelled) {
        return seedSheet(path_, input, first, count, width, cancelled);
    });
}

ApiReply GrammarJobs::infer(const InferInput& input) {
    const std::uint64_t mine = ++latestRun_;
    rt::interruptDerivation();
    return onWorker([this, input, mine] {
        return inferExample(path_, input, [this, mine] { return latestRun_.load() != mine; });
    });
}

void GrammarJobs::cancelRuns() {
    ++latestRun_;
    rt::interruptDerivation();
}

}  // namespace g2d::studio
