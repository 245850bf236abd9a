#include "core/image/fft_convolution.h"

#include <fftw3.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>

namespace caustica {

int fft_length(int n) {
  for (int m = n < 1 ? 1 : n;; ++m) {
    int r = m;
    for (int p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

namespace {
namespace CAUSTICA_UNITY_ID {

// FFTW's planner is not thread-safe; executing a plan is.
std::mutex& planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

struct FloatBuffer {
  explicit FloatBuffer(size_t n) : data(static_cast<float*>(fftwf_malloc(n * sizeof(float)))) {
    if (!data) throw std::bad_alloc();
  }
  ~FloatBuffer() { fftwf_free(data); }
  FloatBuffer(const FloatBuffer&) = delete;
  FloatBuffer& operator=(const FloatBuffer&) = delete;
  float* data;
};

// An in-place real transform pair over an M x N grid whose rows are padded
// to 2 (N / 2 + 1) floats.
class RealTransforms {
 public:
  RealTransforms(int rows, int cols, float* buffer) {
    std::lock_guard<std::mutex> lock(planner_mutex());
    static std::once_flag threads_ready;
    std::call_once(threads_ready, [] { fftwf_init_threads(); });
    fftwf_plan_with_nthreads(int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
    auto* spectrum = reinterpret_cast<fftwf_complex*>(buffer);
    forward_ = fftwf_plan_dft_r2c_2d(rows, cols, buffer, spectrum, FFTW_ESTIMATE);
    inverse_ = fftwf_plan_dft_c2r_2d(rows, cols, spectrum, buffer, FFTW_ESTIMATE);
    if (!forward_ || !inverse_) throw std::runtime_error("FFTW could not plan a transform");
  }
  ~RealTransforms() {
    std::lock_guard<std::mutex> lock(planner_mutex());
    fftwf_destroy_plan(forward_);
    fftwf_destroy_plan(inverse_);
  }
  RealTransforms(const RealTransforms&) = delete;
  RealTransforms& operator=(const RealTransforms&) = delete;
  void forward() const { fftwf_execute(forward_); }
  void inverse() const { fftwf_execute(inverse_); }

 private:
  fftwf_plan forward_ = nullptr, inverse_ = nullptr;
};

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

void convolve(std::vector<float>& pixels, int width, int height, int channels, const EvenKernel& kernel) {
  if (width <= 0 || height <= 0) return;
  // Offsets beyond the image never pair two of its pixels.
  const int reach_x = std::min(kernel.width, width), reach_y = std::min(kernel.height, height);
  // A circular transform of at least width + reach - 1 keeps every offset
  // that pairs two pixels apart from every other.
  const int cols = fft_length(width + reach_x - 1), rows = fft_length(height + reach_y - 1);
  const size_t stride = 2 * (size_t(cols) / 2 + 1);
  const size_t half = stride / 2;
  FloatBuffer buffer(stride * size_t(rows));
  const RealTransforms transforms(rows, cols, buffer.data);

  // The kernel is even, so its spectrum is real: only that is kept.
  const auto circular = [](int i, int n, int extent) { return i < extent ? i : (i > n - extent ? n - i : -1); };
  tbb::parallel_for(0, rows, [&](int y) {
    const int dy = circular(y, rows, reach_y);
    float* row = buffer.data + size_t(y) * stride;
    for (int x = 0; x < cols; ++x) {
      const int dx = circular(x, cols, reach_x);
      row[x] = dx >= 0 && dy >= 0 ? float(kernel.at(dx, dy)) : 0.0f;
    }
  });
  transforms.forward();
  std::vector<float> kernel_spectrum(half * size_t(rows));
  const float normalisation = 1.0f / (float(cols) * float(rows));
  tbb::parallel_for(0, rows, [&](int y) {
    for (size_t i = size_t(y) * half; i < size_t(y + 1) * half; ++i)
      kernel_spectrum[i] = buffer.data[2 * i] * normalisation;
  });

  for (int c = 0; c < channels; ++c) {
    tbb::parallel_for(0, rows, [&](int y) {
      float* row = buffer.data + size_t(y) * stride;
      if (y < height) {
        const float* source = pixels.data() + size_t(y) * width * channels + c;
        for (int x = 0; x < width; ++x) row[x] = source[size_t(x) * channels];
        std::fill(row + width, row + stride, 0.0f);
      } else {
        std::fill(row, row + stride, 0.0f);
      }
    });
    transforms.forward();
    tbb::parallel_for(0, rows, [&](int y) {
      for (size_t i = size_t(y) * half; i < size_t(y + 1) * half; ++i) {
        buffer.data[2 * i] *= kernel_spectrum[i];
        buffer.data[2 * i + 1] *= kernel_spectrum[i];
      }
    });
    transforms.inverse();
    tbb::parallel_for(0, height, [&](int y) {
      const float* row = buffer.data + size_t(y) * stride;
      float* target = pixels.data() + size_t(y) * width * channels + c;
      for (int x = 0; x < width; ++x) target[size_t(x) * channels] = row[x];
    });
  }
}

}  // namespace caustica
