#include "design/workflow/cluster.hpp"

#include <cstdlib>

#ifdef SPIRAL_HAVE_MPI
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <deque>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#endif

namespace spiral::design {

#ifdef SPIRAL_HAVE_MPI

namespace {

constexpr int kTagWork = 1;    ///< rank 0 → worker: the task index (or kStop)
constexpr int kTagResult = 2;  ///< worker → rank 0: the index, then the result bytes
constexpr std::uint64_t kStop = ~std::uint64_t{0};

class MpiCluster final : public Cluster {
 public:
  MpiCluster() {
    int provided = 0;
    // Only the calling thread talks MPI; rank 0's second thread computes.
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiCluster() override { MPI_Finalize(); }

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void broadcast(Bytes& bytes) const override {
    std::uint64_t n = bytes.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    bytes.resize(n);
    // MPI counts are int: large payloads go in chunks.
    constexpr std::uint64_t kChunk = 1u << 30;
    for (std::uint64_t at = 0; at < n; at += kChunk)
      MPI_Bcast(bytes.data() + at, static_cast<int>(std::min(kChunk, n - at)), MPI_BYTE, 0, MPI_COMM_WORLD);
  }

  void distribute(const std::vector<std::size_t>& order, const std::function<Bytes(std::size_t)>& work,
                  const std::function<void(std::size_t, Bytes)>& on_result) const override {
    if (rank_ == 0)
      serve(order, work, on_result);
    else
      compute(work);
  }

 private:
  void serve(const std::vector<std::size_t>& order, const std::function<Bytes(std::size_t)>& work,
             const std::function<void(std::size_t, Bytes)>& on_result) const {
    std::mutex mutex;
    std::deque<std::size_t> queue(order.begin(), order.end());
    std::deque<std::pair<std::size_t, Bytes>> local_done;
    const auto next = [&]() -> std::optional<std::size_t> {
      std::lock_guard lock(mutex);
      if (queue.empty()) return std::nullopt;
      const std::size_t i = queue.front();
      queue.pop_front();
      return i;
    };
    // Rank 0 computes too, on a thread of its own, while this thread serves.
    std::thread local([&] {
      while (const std::optional<std::size_t> i = next()) {
        Bytes result = work(*i);
        std::lock_guard lock(mutex);
        local_done.emplace_back(*i, std::move(result));
      }
    });
    std::size_t received = 0;
    int busy = 0;
    for (int r = 1; r < size_; ++r) busy += send(r, next()) ? 1 : 0;
    while (received < order.size()) {
      bool idle = true;
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &status);
      if (flag) {
        int count = 0;
        MPI_Get_count(&status, MPI_BYTE, &count);
        Bytes message(static_cast<std::size_t>(count));
        MPI_Recv(message.data(), count, MPI_BYTE, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        std::uint64_t index = 0;
        std::memcpy(&index, message.data(), sizeof index);
        --busy;
        busy += send(status.MPI_SOURCE, next()) ? 1 : 0;
        on_result(index, Bytes(message.begin() + sizeof index, message.end()));
        ++received;
        idle = false;
      }
      std::deque<std::pair<std::size_t, Bytes>> done;
      {
        std::lock_guard lock(mutex);
        done.swap(local_done);
      }
      for (auto& [i, bytes] : done) {
        on_result(i, std::move(bytes));
        ++received;
        idle = false;
      }
      if (idle) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    local.join();
    // Every worker was sent a stop when the queue ran dry (send with none).
  }

  /// Sends the next task, or a stop when there is none; true when a task was sent.
  bool send(int rank, std::optional<std::size_t> index) const {
    const std::uint64_t value = index ? static_cast<std::uint64_t>(*index) : kStop;
    MPI_Send(&value, 1, MPI_UINT64_T, rank, kTagWork, MPI_COMM_WORLD);
    return index.has_value();
  }

  void compute(const std::function<Bytes(std::size_t)>& work) const {
    while (true) {
      std::uint64_t index = 0;
      MPI_Recv(&index, 1, MPI_UINT64_T, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (index == kStop) return;
      const Bytes result = work(static_cast<std::size_t>(index));
      Bytes message(sizeof index + result.size());
      std::memcpy(message.data(), &index, sizeof index);
      std::copy(result.begin(), result.end(), message.begin() + sizeof index);
      if (message.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::runtime_error("a task result larger than 2 GB cannot be sent between MPI ranks");
      MPI_Send(message.data(), static_cast<int>(message.size()), MPI_BYTE, 0, kTagResult, MPI_COMM_WORLD);
    }
  }

  int rank_ = 0;
  int size_ = 1;
};

}  // namespace

std::unique_ptr<Cluster> launched_cluster() {
  // mpirun (Open MPI) tells its processes the job size; a plain start is one process.
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (size == nullptr || std::atoi(size) < 2) return nullptr;
  return std::make_unique<MpiCluster>();
}

bool built_with_mpi() { return true; }

#else

std::unique_ptr<Cluster> launched_cluster() { return nullptr; }

bool built_with_mpi() { return false; }

#endif

}  // namespace spiral::design
