// Compares two PNGs of the same size pixel by pixel, e.g. one frame rendered on two devices.
//
//   image_diff a.png b.png [threshold]   -> how many pixels differ, and by more than threshold levels
#include <stb_image.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: image_diff A.png B.png [threshold, default 8]\n");
    return 2;
  }
  const int threshold = argc == 4 ? std::atoi(argv[3]) : 8;
  int w = 0, h = 0, wb = 0, hb = 0, n = 0;
  const std::unique_ptr<unsigned char, decltype(&stbi_image_free)> a(stbi_load(argv[1], &w, &h, &n, 4), stbi_image_free);
  const std::unique_ptr<unsigned char, decltype(&stbi_image_free)> b(stbi_load(argv[2], &wb, &hb, &n, 4), stbi_image_free);
  if (!a || !b || w != wb || h != hb) {
    std::fprintf(stderr, "image_diff: cannot compare '%s' and '%s': unreadable, or sizes differ\n", argv[1], argv[2]);
    return 1;
  }
  long differ = 0, above = 0;
  int largest = 0;
  for (long i = 0; i < long{w} * h; ++i) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a.get()[i * 4 + c] - b.get()[i * 4 + c]));
    differ += d > 0;
    above += d > threshold;
    largest = std::max(largest, d);
  }
  std::printf("%dx%d: %ld pixels differ (%.2f%%), %ld by more than %d levels (%.2f%%), largest difference %d\n", w, h,
              differ, 100.0 * differ / (double(w) * h), above, threshold, 100.0 * above / (double(w) * h), largest);
  return 0;
}
