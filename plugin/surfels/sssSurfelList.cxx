#include "sssSurfelList.h"

#include "sssGpuHelpers.h"

#include "local_surfels.h"
#include "hilbert_order.h"
#include "surfel_cells.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <cmath>
#include <utility>

namespace sss
{

namespace
{
int CeilLog2(std::size_t n)
{
  int k = 0;
  while ((std::size_t(1) << k) < n)
  {
    ++k;
  }
  return k;
}

// The texel of list position `rank` in a 2^xbits x 2^ybits layout: its bits dealt to x and y
// in turn (x first), an axis that is full skipped, so that every 2^k x 2^k square holds
// consecutive ranks.
std::pair<int, int> MortonTexel(std::size_t rank, int xbits, int ybits)
{
  int x = 0, y = 0, xi = 0, yi = 0;
  for (int bit = 0; bit < xbits + ybits; ++bit)
  {
    const int value = static_cast<int>((rank >> bit) & 1u);
    const bool to_x = xi < xbits && (yi >= ybits || xi <= yi);
    if (to_x)
    {
      x |= value << xi++;
    }
    else
    {
      y |= value << yi++;
    }
  }
  return { x, y };
}
}

SurfelList::SurfelList() = default;
SurfelList::~SurfelList() = default;

bool SurfelList::upload(vtkOpenGLRenderWindow* window, const LocalSurfels& local,
  const SurfelCells& cells, std::string& error)
{
  const std::size_t n = local.size();
  const std::vector<std::size_t> order = hilbert_order(local.positions);
  const int bits = CeilLog2(std::max<std::size_t>(n, 1));
  const int xbits = (bits + 1) / 2, ybits = bits - xbits;
  width_ = 1 << xbits;
  height_ = 1 << ybits;
  if (width_ > 16384 || height_ > 16384)
  {
    error = "too many surfels for one list texture";
    return false;
  }
  texel_of_.assign(n, 0);
  for (std::size_t rank = 0; rank < n; ++rank)
  {
    const auto [x, y] = MortonTexel(rank, xbits, ybits);
    texel_of_[order[rank]] = static_cast<std::size_t>(y) * width_ + x;
  }
  const std::size_t texels = static_cast<std::size_t>(width_) * height_;
  std::vector<float> point(4 * texels, 0.0f), shape(4 * texels, 0.0f), cell(4 * texels, 0.0f),
    albedo(4 * texels, 0.0f);
  std::vector<float> at(2 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t t = texel_of_[i];
    for (int c = 0; c < 3; ++c)
    {
      point[4 * t + c] = static_cast<float>(local.positions[i][c]);
      shape[4 * t + c] = static_cast<float>(local.normals[i][c]);
      albedo[4 * t + c] = static_cast<float>(local.albedo.empty() ? 1.0 : local.albedo[i][c]);
    }
    point[4 * t + 3] = static_cast<float>(local.thickness(i));
    shape[4 * t + 3] = static_cast<float>(local.curvature[i]);
    cell[4 * t] = static_cast<float>(std::sqrt(cells.area[i] / M_PI));
    cell[4 * t + 1] = static_cast<float>(cells.area[i]);
    cell[4 * t + 2] = static_cast<float>(local.disc_radius(i));
    cell[4 * t + 3] = static_cast<float>(local.noise_height(i));
    at[2 * i] = static_cast<float>(t % width_);
    at[2 * i + 1] = static_cast<float>(t / width_);
  }
  point_ = upload_float_texture(window, width_, height_, point);
  shape_ = upload_float_texture(window, width_, height_, shape);
  cell_ = upload_float_texture(window, width_, height_, cell);
  albedo_ = upload_float_texture(window, width_, height_, albedo);
  texel_->Upload(at, vtkOpenGLBufferObject::ArrayBuffer);
  return true;
}

void SurfelList::activate() const
{
  for (vtkTextureObject* t : { point_.Get(), shape_.Get(), cell_.Get(), albedo_.Get() })
  {
    t->Activate();
  }
}

void SurfelList::deactivate() const
{
  for (vtkTextureObject* t : { point_.Get(), shape_.Get(), cell_.Get(), albedo_.Get() })
  {
    t->Deactivate();
  }
}

void SurfelList::set(vtkShaderProgram* program) const
{
  program->SetUniformi("surfelPoint", point_->GetTextureUnit());
  program->SetUniformi("surfelShape", shape_->GetTextureUnit());
  program->SetUniformi("surfelCell", cell_->GetTextureUnit());
  program->SetUniformi("surfelAlbedo", albedo_->GetTextureUnit());
}

void SurfelList::release(vtkWindow* window)
{
  release_held(window, point_, shape_, cell_, albedo_);
  texel_->ReleaseGraphicsResources();
}

}
