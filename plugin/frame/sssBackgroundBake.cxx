#include "sssBackgroundBake.h"

#include <exception>

namespace sss
{

BackgroundBake::~BackgroundBake()
{
  for (auto& [thread, job] : threads_)
  {
    thread.join();
  }
}

void BackgroundBake::start(BakeWork work)
{
  join_finished();
  job_ = std::make_shared<Job>();
  job_->work = std::move(work);
  std::shared_ptr<Job> job = job_;
  threads_.emplace_back(std::thread([job] {
    try
    {
      job->result = job->work();
    }
    catch (const std::exception& e)
    {
      job->error = e.what();
    }
    job->finished = true;
  }),
    job);
}

void BackgroundBake::drop()
{
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
