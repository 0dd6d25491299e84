#include "sssNearFieldTable.h"

#include "sssGpuHelpers.h"
#include "sssSurfelList.h"

#include "near_field.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

namespace sss
{

namespace
{
constexpr int kEntriesWidth = 4096;
}

bool NearFieldTable::upload(vtkOpenGLRenderWindow* window, const SurfelList& list,
  const NearFieldWeights& weights, std::string& error)
{
  const std::size_t entry_count = std::max<std::size_t>(weights.source.size(), 1);
  const int entries_w = static_cast<int>(std::min<std::size_t>(entry_count, kEntriesWidth));
  const int entries_h = static_cast<int>((entry_count + entries_w - 1) / entries_w);
  if (entries_h > 16384)
  {
    error = "the near-field table has too many entries for one texture";
    return false;
  }
  std::vector<float> rows(4 * static_cast<std::size_t>(list.width()) * list.height(), 0.0f);
  for (std::size_t i = 0; i < weights.rows(); ++i)
  {
    const std::size_t t = list.texel_of(i);
    rows[4 * t] = static_cast<float>(weights.first[i]);
    rows[4 * t + 1] = static_cast<float>(weights.first[i + 1] - weights.first[i]);
  }
  std::vector<float> entries(4 * static_cast<std::size_t>(entries_w) * entries_h, 0.0f);
  for (std::size_t e = 0; e < weights.source.size(); ++e)
  {
    entries[4 * e] = static_cast<float>(list.texel_of(weights.source[e]));
    for (int c = 0; c < 3; ++c)
    {
      entries[4 * e + 1 + c] = static_cast<float>(weights.weight[e][c]);
    }
  }
  rows_ = upload_float_texture(window, list.width(), list.height(), rows);
  entries_ = upload_float_texture(window, entries_w, entries_h, entries);
  return true;
}

void NearFieldTable::activate(vtkShaderProgram* program) const
{
  rows_->Activate();
  entries_->Activate();
  program->SetUniformi("nearRows", rows_->GetTextureUnit());
  program->SetUniformi("nearEntries", entries_->GetTextureUnit());
}

void NearFieldTable::deactivate() const
{
  entries_->Deactivate();
  rows_->Deactivate();
}

void NearFieldTable::release(vtkWindow* window)
{
  release_held(window, rows_, entries_);
}

}
