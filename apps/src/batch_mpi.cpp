#include "batch_mpi.h"

#ifdef TETBLEND_WITH_MPI

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace tetblend::cli {
namespace {

constexpr int kTagRequest = 1;
constexpr int kTagJob = 2;
constexpr int kTagBye = 3;

bool launchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

void sendText(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

class MpiWorld final : public BatchWorld {
 public:
  MpiWorld(int rank, int size, int level) : rank_(rank), size_(size), level_(level) {}
  ~MpiWorld() override { MPI_Finalize(); }

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  bool threadsMayTalk() const override { return level_ >= MPI_THREAD_SERIALIZED; }

  [[noreturn]] void abort(const std::string& why) override {
    std::fprintf(stderr, "tetblend: error: %s\n", why.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::_Exit(1);
  }

  void start(bool ok, std::uint64_t inputs, const std::vector<std::int64_t>& pending) override {
    unsigned long long head[2] = {ok ? pending.size() : ~0ull, inputs};
    MPI_Bcast(head, 2, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    const auto count = static_cast<long long>(pending.size());
    if (!ok || count == 0) return;
    std::vector<long long> jobs(pending.begin(), pending.end());
    MPI_Bcast(jobs.data(), static_cast<int>(count), MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  }

  void serve(const std::function<std::int64_t()>& nextJob,
             const std::function<void(int, const std::string&)>& onOutcome,
             const std::function<void(int, const std::string&)>& onRetired) override {
    for (int byes = 0; byes < size_ - 1;) {
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (!flag) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        continue;
      }
      int length = 0;
      MPI_Get_count(&status, MPI_CHAR, &length);
      std::string text(static_cast<std::size_t>(length), '\0');
      MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      if (status.MPI_TAG == kTagRequest) {
        if (!text.empty()) onOutcome(status.MPI_SOURCE, text);
        long long job = nextJob();
        MPI_Send(&job, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagJob, MPI_COMM_WORLD);
      } else if (status.MPI_TAG == kTagBye) {
        ++byes;
        if (!text.empty()) onRetired(status.MPI_SOURCE, text);
      }
    }
  }

  bool awaitStart(std::uint64_t& inputs, std::vector<std::int64_t>& pending) override {
    unsigned long long head[2] = {0, 0};
    MPI_Bcast(head, 2, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    if (head[0] == ~0ull) return false;
    inputs = head[1];
    const auto count = static_cast<long long>(head[0]);
    std::vector<long long> jobs(static_cast<std::size_t>(count));
    if (count > 0)
      MPI_Bcast(jobs.data(), static_cast<int>(count), MPI_LONG_LONG, 0, MPI_COMM_WORLD);
    pending.assign(jobs.begin(), jobs.end());
    return true;
  }

  std::int64_t requestJob(const std::string& outcome) override {
    std::lock_guard<std::mutex> lock(mutex_);
    sendText(outcome, 0, kTagRequest);
    long long job = -1;
    MPI_Recv(&job, 1, MPI_LONG_LONG, 0, kTagJob, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return job;
  }

  void bye(const std::string& reason) override {
    std::lock_guard<std::mutex> lock(mutex_);
    sendText(reason, 0, kTagBye);
  }

 private:
  int rank_;
  int size_;
  int level_;
  std::mutex mutex_;
};

}  // namespace

std::unique_ptr<BatchWorld> joinBatchWorld() {
  if (!launchedByMpi()) return nullptr;
  int level = MPI_THREAD_SINGLE;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &level);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2) {
    MPI_Finalize();
    return nullptr;
  }
  return std::make_unique<MpiWorld>(rank, size, level);
}

}  // namespace tetblend::cli

#else  // built without MPI: every batch is one process

namespace tetblend::cli {
std::unique_ptr<BatchWorld> joinBatchWorld() { return nullptr; }
}  // namespace tetblend::cli

#endif
