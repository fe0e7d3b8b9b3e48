// EffectTextureCache: bake/decode once, upload once, stand-ins for missing files.
#include "fx/binding/effect_textures.h"

#include <cctype>
#include <system_error>
#include <variant>

#include "fx/shading/generator.h"

namespace fx::vk {
namespace {

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// Generator parameters in a canonical order (the map is sorted by lower-cased name).
std::string generator_key(const TextureInfo& t) {
  std::string key = "gen:" + t.generator;
  for (const auto& [name, value] : t.generator_params.entries()) {
    key += ';' + name + '=';
    if (const double* d = std::get_if<double>(&value)) key += std::to_string(*d);
    else key += std::get<std::string>(value);
  }
  return key;
}

// A 1x1 texel that leaves the shading it feeds neutral: a normal map's "straight out of
// the surface", white for colours and masks, a depth of 1.0 for a depth comparison (a shadow
// map nothing is in front of). Made in the shape the shader samples.
enum class StandIn { white, flat_normal, depth, multisampled };

std::string stand_in_key(StandIn kind, ImageDim dim, bool arrayed) {
  const char* name = kind == StandIn::flat_normal    ? "normal"
                     : kind == StandIn::depth        ? "depth"
                     : kind == StandIn::multisampled ? "multisampled"
                                                     : "white";
  return std::string("stand-in:") + name + ":" + std::to_string(int(dim)) + (arrayed ? ":array" : "");
}

EffectTextureData stand_in(StandIn kind, ImageDim dim, bool arrayed) {
  EffectTextureData d;
  d.key = stand_in_key(kind, dim, arrayed);
  d.dim = dim;
  d.arrayed = arrayed;
  d.stand_in = true;
  d.depth = kind == StandIn::depth;
  d.multisampled = kind == StandIn::multisampled;
  if (d.depth) return d;  // uploaded by Texture::solid_depth
  const uint8_t c = kind == StandIn::flat_normal ? 128 : 255;
  fx::Image image = fx::Image::blank(1, 1, 4);
  const uint8_t texel[4] = {c, c, 255, 255};
  std::copy(texel, texel + 4, image.pixels.begin());
  d.image = std::move(image);
  return d;
}

ImageKind image_kind(ImageDim dim) {
  switch (dim) {
    case ImageDim::dim_1d: return ImageKind::image1d;
    case ImageDim::dim_3d: return ImageKind::image3d;
    case ImageDim::cube: return ImageKind::cube;
    default: return ImageKind::image2d;
  }
}

}  // namespace

std::shared_ptr<const EffectTextureData> EffectTextureCache::resolve(const EffectModel& model,
                                                                     const TextureInfo& texture,
                                                                     const std::filesystem::path& effect_dir,
                                                                     ImageDim dim, bool arrayed, DiagnosticSink& sink) {
  const Parameter* param = texture.parameter < model.parameters.size() ? &model.parameters[texture.parameter] : nullptr;
  const bool normal_map = param && (iequals(param->semantic, "NORMALMAP") || iequals(param->semantic, "NORMAL"));
  const StandIn neutral = normal_map ? StandIn::flat_normal : StandIn::white;
  std::string key;
  std::filesystem::path file;
  if (!texture.generator.empty()) {
    key = generator_key(texture);
  } else if (!texture.resource_name.empty()) {
    file = std::filesystem::path(texture.resource_name);
    if (file.is_relative()) file = effect_dir / file;
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    if (!ec) {
      const auto mtime = std::filesystem::last_write_time(file, ec).time_since_epoch().count();
      key = "file:" + file.lexically_normal().string() + ':' + std::to_string(size) + ':' + std::to_string(mtime);
    } else {
      sink.warning("vk-texture-file-missing", param ? param->range : SourceRange{},
                   "texture file '" + file.string() + "' of '" + (param ? param->name : std::string()) +
                       "' cannot be read; a neutral " + (normal_map ? "flat normal" : "white") + " texture stands in");
      key = stand_in_key(neutral, dim, arrayed);
    }
  } else {
    key = stand_in_key(neutral, dim, arrayed);
  }
  if (auto hit = cached(key)) return hit;
  // Baking can take a while (BRDF factorisation): done outside the lock, so two threads may
  // race to bake the same table; the first to insert wins and both get equal data.
  EffectTextureData data;
  if (key.rfind("stand-in:", 0) == 0) {
    data = stand_in(neutral, dim, arrayed);
  } else if (!texture.generator.empty()) {
    auto table = shading::bake(texture.generator, texture.generator_params, sink, texture.generator_range);
    if (!table) return nullptr;
    data.table = std::move(*table);
  } else {
    DiagnosticSink decode;
    auto image = fx::read_png(file, decode);
    if (!image) {
      sink.warning("vk-texture-file-missing", param ? param->range : SourceRange{},
                   "texture file '" + file.string() + "' cannot be decoded; a neutral texture stands in");
      data = stand_in(neutral, dim, arrayed);
    } else {
      data.image = std::move(*image);
    }
  }
  data.key = key;
  return keep(std::move(data));
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::depth_stand_in(ImageDim dim, bool arrayed) {
  if (auto hit = cached(stand_in_key(StandIn::depth, dim, arrayed))) return hit;
  return keep(stand_in(StandIn::depth, dim, arrayed));
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::multisampled_stand_in(bool arrayed) {
  if (auto hit = cached(stand_in_key(StandIn::multisampled, ImageDim::dim_2d, arrayed))) return hit;
  return keep(stand_in(StandIn::multisampled, ImageDim::dim_2d, arrayed));
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::cached(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = cpu_.find(key);
  return it != cpu_.end() ? it->second : nullptr;
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::keep(EffectTextureData data) {
  std::string key = data.key;
  auto shared = std::make_shared<const EffectTextureData>(std::move(data));
  std::lock_guard<std::mutex> lock(mutex_);
  return cpu_.emplace(std::move(key), std::move(shared)).first->second;  // the first to insert wins
}

const Texture* EffectTextureCache::gpu(const EffectTextureData& data, DiagnosticSink& sink) {
  if (auto it = gpu_.find(data.key); it != gpu_.end()) return &it->second;
  std::optional<Texture> texture;
  if (data.depth) {
    texture = Texture::solid_depth(*ctx_, 1.0f, image_kind(data.dim), data.arrayed, sink);
  } else if (data.multisampled) {
    const uint8_t* p = data.image->pixels.data();
    texture = Texture::solid_multisampled(*ctx_, {p[0], p[1], p[2], p[3]}, data.arrayed, sink);
  } else if (data.stand_in) {
    const uint8_t* p = data.image->pixels.data();
    texture = Texture::solid(*ctx_, {p[0], p[1], p[2], p[3]}, image_kind(data.dim), data.arrayed, sink);
  } else if (data.table) texture = Texture::from_table(*ctx_, *data.table, sink);
  else if (data.image) texture = Texture::from_image(*ctx_, *data.image, ColorSpace::linear, sink);
  if (!texture) return nullptr;
  return &gpu_.emplace(data.key, std::move(*texture)).first->second;
}

size_t EffectTextureCache::cpu_count() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return cpu_.size();
}

void EffectTextureCache::clear() {
  gpu_.clear();
  std::lock_guard<std::mutex> lock(mutex_);
  cpu_.clear();
}

}  // namespace fx::vk
