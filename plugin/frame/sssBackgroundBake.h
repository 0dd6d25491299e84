// The CPU part of a bake (Strategy::bake_work) on a thread of its own, so that the frames of a
// refinement go on drawing the preview while it runs (sssTranslucentActorState).
#ifndef sssBackgroundBake_h
#define sssBackgroundBake_h

#include "sssStrategy.h"

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace sss
{

class BackgroundBake
{
public:
  BackgroundBake() = default;
  ~BackgroundBake();  // waits for every thread it started
  BackgroundBake(const BackgroundBake&) = delete;
  BackgroundBake& operator=(const BackgroundBake&) = delete;

  // Runs `work` on a new thread; a run under way is dropped.
  void start(BakeWork work);
  // Drops the run under way, if any: it is cancelled and its thread joined once it has stopped.
  // The destructor cancels every run and waits for their threads.
  void drop();
  // Whether a run was started and not taken or dropped, and whether it has finished.
  bool running() const { return job_ != nullptr; }
  bool finished() const { return job_ && job_->finished.load(); }
  // Blocks until the run under way, if any, has finished.
  void wait();
  // The finished run's result, or null with `error` set to what the work threw; ends the run.
  std::unique_ptr<BakePreparation> take(std::string& error);

private:
  struct Job
  {
    BakeWork work;
    std::unique_ptr<BakePreparation> result;
    std::string error;
    std::atomic<bool> finished{ false };
    CancelFlag cancel{ false };
  };
  // Joins the threads whose runs have finished.
  void join_finished();

  std::shared_ptr<Job> job_;
  std::vector<std::pair<std::thread, std::shared_ptr<Job>>> threads_;
};

}

#endif
