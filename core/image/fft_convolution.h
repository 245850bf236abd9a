#pragma once

#include <vector>

#include "core/image/even_kernel.h"

namespace caustica {

// Convolves each channel of a pixel-interleaved image with `kernel`, as if
// the image were black outside its frame: light spread past the frame is
// lost, none comes back from the other side. FFTW transforms padded by
// the kernel's reach (at most the image again), on as many threads as TBB
// may use.
void convolve(std::vector<float>& pixels, int width, int height, int channels, const EvenKernel& kernel);

// The smallest length of at least n whose only prime factors are 2, 3, 5
// and 7, which FFTW transforms fastest.
int fft_length(int n);

}  // namespace caustica
