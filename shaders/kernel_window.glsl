// Splits the kernel by distance (core/kernel_window.h): the near part is kept per surfel, the
// smooth far part is carried by the virtual grid. A quintic smoothstep from r0 to r1.

uniform int windowPart;  // 0: all of the kernel, 1: near part, 2: far part
uniform float windowR0;  // mm
uniform float windowR1;  // mm

float kernelWindow(float r)
{
  if (windowPart == 0)
  {
    return 1.0;
  }
  float t = clamp((r - windowR0) / (windowR1 - windowR0), 0.0, 1.0);
  float far = t * t * t * (t * (6.0 * t - 15.0) + 10.0);
  return windowPart == 2 ? far : 1.0 - far;
}
