#include "sssBackgroundBake.h"

#include "stopwatch.h"

#include <exception>

namespace sss
{

BackgroundBake::~BackgroundBake()
{
  for (auto& [thread, job] : threads_)
  {
    job->cancel = true;
  }
  for (auto& [thread, job] : threads_)
  {
    thread.join();
  }
}

void BackgroundBake::start(BakeWork work)
{
  drop();
  auto job = std::make_shared<Job>();
  job->work = std::move(work);
  threads_.reserve(threads_.size() + 1);  // emplace_back below cannot throw with a thread built
  std::thread thread([job] {
    try
    {
      Stopwatch clock;
      job->result = job->work(job->cancel);
      if (job->result)
      {
        job->result->seconds = clock.lap();
      }
    }
    catch (const std::exception& e)
    {
      job->error = e.what();
    }
    catch (...)
    {
      job->error = "the bake's preparation failed";
    }
    job->finished = true;
  });
  threads_.emplace_back(std::move(thread), job);
  job_ = std::move(job);
}

void BackgroundBake::drop()
{
  if (job_)
  {
    job_->cancel = true;  // its result is not wanted: the work stops at its next check
  }
  job_ = nullptr;
  join_finished();
}

void BackgroundBake::wait()
{
  for (auto it = threads_.begin(); it != threads_.end(); ++it)
  {
    if (it->second == job_)
    {
      it->first.join();
      threads_.erase(it);
      return;
    }
  }
}

std::unique_ptr<BakePreparation> BackgroundBake::take(std::string& error)
{
  std::unique_ptr<BakePreparation> result;
  if (job_ && job_->finished)
  {
    result = std::move(job_->result);
    if (!result)
    {
      error = job_->error.empty() ? "the bake's preparation gave nothing" : job_->error;
    }
  }
  job_ = nullptr;
  join_finished();
  return result;
}

void BackgroundBake::join_finished()
{
  for (auto it = threads_.begin(); it != threads_.end();)
  {
    if (it->second->finished)
    {
      it->first.join();
      it = threads_.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

}
