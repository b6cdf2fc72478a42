// Tests for proceduray/scene/compile.hpp: compile(scene) lays every entry out as the Vulkan index rule
// reads it, fills the records with their data, and refuses scenes with missing or doubled entries.
#include "proceduray/scene/compile.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <tuple>

#include "scene_fixtures.hpp"

using namespace proceduray;
using namespace proceduray::test;

namespace {

// An entry whose arguments type differs from its local signature's does not compile.
template <class Signature, class Arguments>
concept CanAddHit = requires(Scene<ReportInterface> t, RayId<> r, HitGroupId h, Signature s, Arguments a, GeometryId g) {
  t.add_hit(r, h, s, a, g);
};
struct OtherArgs { std::uint32_t x; };
PROCEDURAY_STRUCT(OtherArgs, scalar, x);
static_assert(CanAddHit<LocalSignatureId<ProceduralRootArguments>, ProceduralRootArguments>);
static_assert(!CanAddHit<LocalSignatureId<ProceduralRootArguments>, TriangleRootArguments>);
static_assert(!CanAddHit<LocalSignatureId<OtherArgs>, std::uint32_t>);
static_assert(!CanAddHit<LocalSignatureId<>, OtherArgs>);  // an untyped id cannot carry data

template <class Signature, class Arguments>
concept CanAddMiss = requires(Scene<ReportInterface> t, RayId<> r, Signature s, Arguments a) { t.add_miss(r, s, a); };
static_assert(CanAddMiss<LocalSignatureId<OtherArgs>, OtherArgs>);
static_assert(!CanAddMiss<LocalSignatureId<OtherArgs>, TriangleRootArguments>);

template <class T>
bool bytes_equal(std::span<const std::byte> bytes, const T& value) {
  return bytes.size() == sizeof(T) && std::memcmp(bytes.data(), &value, sizeof(T)) == 0;
}

}  // namespace

TEST_CASE("compile report scene resolves every ray geometry and instance") {
  ReportScene r;
  build_report_scene(r);
  add_report_entries(r);
  const Plan sbt = compile(r.scene);
  // The plan depends on no device: every profile lays it out.
  for (const DeviceLimits& limits : all_limits()) CHECK(sbt.layout(limits).region(SbtRegionKind::hit).count == 14);
  CHECK(sbt.ray_count() == 2);
  // Triangle plane: one shared block; each fractal instance has its own entries.
  CHECK(sbt.records(SbtRegionKind::hit).size() == 2 + 2 * (2 + 3 + 1));
  CHECK(sbt.instances().size() == 7);
  CHECK(sbt.instance_sbt_offset(r.plane, 0) == 0);
  CHECK(sbt.instance_sbt_offset(r.julia, 0) == 2);
  CHECK(sbt.instance_sbt_offset(r.julia, 1) == 4);
  CHECK(sbt.instance_sbt_offset(r.pacman, 2) == 10);
  CHECK(sbt.instance_sbt_offset(r.mandelbulb, 0) == 12);
  const auto entries = r.scene.entries().all();
  std::uint32_t instance_index = 0;
  for (GeometryId g : {r.julia, r.pacman, r.mandelbulb}) {
    const std::string name = r.scene.geometries().name(g.index());
    for (std::uint32_t i = 0; i < r.scene.blas_of(g).instances.size(); ++i, ++instance_index) {
      const HitResolution radiance = sbt.resolve(r.radiance, g, i);
      const HitResolution shadow = sbt.resolve(r.shadow, g, i);
      CHECK(r.scene.hit_groups().name(radiance.entry->hit_group) == name);
      CHECK(r.scene.hit_groups().name(shadow.entry->hit_group) == name + "_Shadow");
      CHECK(radiance.entry->instance == i);
      ProceduralRootArguments args;
      std::memcpy(&args, r.scene.entries().data().data() + radiance.entry->arguments_offset, sizeof args);
      CHECK(args.instance_index == instance_index);
      CHECK(bytes_equal(sbt.root_arguments(*radiance.sbt_record), args));
      CHECK(radiance.record == sbt.instance_sbt_offset(g, i) + sbt.geometry_index(g) * 2 + 0);
      CHECK(shadow.record == radiance.record + 1);
      // The plan holds its own copy of the entry the scene holds.
      CHECK(entries[sbt.records(SbtRegionKind::hit)[radiance.record].entry] == *radiance.entry);
      CHECK(sbt.entry(sbt.records(SbtRegionKind::hit)[radiance.record]) == radiance.entry);
    }
  }
  CHECK(r.scene.hit_groups().name(sbt.resolve(r.shadow, r.plane, 0).entry->hit_group) == "Triangle_Shadow");
}

TEST_CASE("compile D3D12 sample 22-record hit table in any insertion order") {
  std::mt19937 rng(22);
  std::vector<std::uint32_t> order(22);
  std::iota(order.begin(), order.end(), 0u);
  for (int trial = 0; trial < 20; ++trial) {
    D3D12Scene d;
    build_d3d12_scene(d);
    add_d3d12_entries(d, order);
    const Plan sbt = compile(d.scene);
    const auto hit = sbt.records(SbtRegionKind::hit);
    REQUIRE(hit.size() == 22);
    CHECK(sbt.layout(trial % 2 ? h100_limits : lavapipe_limits).region(SbtRegionKind::hit).count == 22);
    CHECK(sbt.pipeline().groups.size() == 1 + 2 + 8);  // raygen, 2 miss, 8 hit groups
    // The sample's table: [0] triangle, [1] triangle shadow, then (radiance, shadow) per AABB geometry.
    CHECK(sbt.pipeline().groups[hit[0].group].name == "MyHitGroup_Triangle");
    CHECK(sbt.pipeline().groups[hit[1].group].name == "MyHitGroup_Triangle_ShadowRay");
    for (std::uint32_t a = 0; a < 10; ++a) {
      CHECK(sbt.pipeline().groups[hit[2 + 2 * a].group].name == std::string(d3d12_group_of(a)));
      CHECK(sbt.pipeline().groups[hit[3 + 2 * a].group].name == std::string(d3d12_group_of(a)) + "_ShadowRay");
      CHECK(sbt.geometry_index(d.aabbs[a]) == a);
    }
    // InstanceContributionToHitGroupIndex: 0 for the plane BLAS, 2 for the AABB BLAS.
    CHECK(sbt.instance_sbt_offset(d.plane, 0) == 0);
    CHECK(sbt.instance_sbt_offset(d.aabbs[0], 0) == 2);
    CHECK(sbt.instances().size() == 2);
    // The sample's indexing example: a shadow ray hitting the 2nd AABB geometry -> record 5.
    const HitResolution example = sbt.resolve(d.shadow, d.aabbs[1], 0);
    CHECK(example.record == 1 + 2 * 1 + 2);
    CHECK(example.record == 5);
    // Every record holds the args of the slot it was bound for, whatever the insertion order.
    for (std::uint32_t slot = 0; slot < 22; ++slot) {
      const auto data = sbt.root_arguments(hit[slot]);
      D3D12RootArguments args;
      REQUIRE(data.size() == sizeof args);
      std::memcpy(&args, data.data(), sizeof args);
      CHECK(args.aabb.primitive_type == slot);
    }
    std::shuffle(order.begin(), order.end(), rng);
  }
}

namespace {

struct Args4 { std::uint32_t tag; };
struct Args16 { std::uint32_t tag; std::uint32_t pad[3]; };
struct Args40 { std::uint32_t tag; float values[9]; };
struct TestPayload { float value; };
PROCEDURAY_STRUCT(Args4, scalar, tag);
PROCEDURAY_STRUCT(Args16, scalar, tag, pad);
PROCEDURAY_STRUCT(Args40, scalar, tag, values);
PROCEDURAY_STRUCT(TestPayload, scalar, value);
using TestSceneInterface = proceduray::ShaderInterface<proceduray::Payload<TestPayload>, proceduray::RootComponent<>, proceduray::RootArguments<Args4, Args16, Args40>,
                                   proceduray::Attributes<Args16>>;
using TestScene = proceduray::Scene<TestSceneInterface>;

struct Key {
  std::uint32_t ray, geometry, instance;
  auto operator<=>(const Key&) const = default;
};

/// One random scene: random rays, geometries (some sharing BLASes), instances, bindings,
/// data sizes and insertion order, with the oracle of which entry each record must hold.
class RandomScene {
 public:
  explicit RandomScene(std::uint32_t seed) : m_seed(seed), m_rng(seed) {
    add_entities();
    plan_bindings();
    add_bindings();
  }

  /// Checks every (ray, geometry, instance) against the oracle; returns how many were checked.
  std::uint64_t check() const;

 private:
  struct Planned { Key key; bool is_default; std::uint32_t group; std::uint32_t size_class; std::uint32_t tag; };

  std::uint32_t pick(std::uint32_t n) { return static_cast<std::uint32_t>(m_rng() % n); }
  void add_entities();
  void plan_bindings();
  void plan(Key key, bool is_default, std::uint32_t kind);
  void add_bindings();
  void add_binding(const Planned& p);
  std::uint32_t expected_tag(std::uint32_t r, GeometryId g, std::uint32_t i, std::uint32_t kind) const;

  std::uint32_t m_seed;
  std::mt19937 m_rng;
  TestScene m_scene;
  std::uint32_t m_ray_count = 0;
  std::vector<RayId<TestPayload>> m_rays;
  std::array<std::vector<HitGroupId>, 2> m_groups;
  LocalSignatureId<Args4> m_sig4;
  LocalSignatureId<Args16> m_sig16;
  LocalSignatureId<Args40> m_sig40;
  std::vector<GeometryId> m_geometries;
  std::vector<Planned> m_plan;
  std::uint32_t m_tag = 1;
  std::map<Key, std::uint32_t> m_wide_tag, m_specific_tag;
  std::array<std::vector<std::uint32_t>, 2> m_default_tag;
  std::map<std::uint32_t, std::uint32_t> m_entry_of_tag;
};

void RandomScene::add_entities() {
  TestScene& s = m_scene;
  m_ray_count = 1 + pick(4);
  for (std::uint32_t r = 0; r < m_ray_count; ++r) m_rays.push_back(s.add_ray<TestPayload>("ray" + std::to_string(r), {.miss = "miss" + std::to_string(pick(2))}));
  for (std::uint32_t h = 0; h < 3; ++h) {
    m_groups[0].push_back(s.add_hit_group("tri" + std::to_string(h), {.closest_hit = "chit" + std::to_string(h)}));
    m_groups[1].push_back(s.add_hit_group<Args16>("proc" + std::to_string(h), {.kind = HitGroupKind::procedural,
        .closest_hit = "chit" + std::to_string(h), .intersection = "isect" + std::to_string(h)}));
  }
  m_sig4 = s.add_local_signature<Args4>("a4");
  m_sig16 = s.add_local_signature<Args16>("a16");
  m_sig40 = s.add_local_signature<Args40>("a40");
  const std::uint32_t geometry_count = 1 + pick(6);
  const std::array<GeometryKind, 2> shared_kind{GeometryKind(pick(2)), GeometryKind(pick(2))};
  TriangleMesh tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}};
  for (std::uint32_t g = 0; g < geometry_count; ++g) {
    const std::uint32_t blas = pick(3);  // 0: own, 1/2: shared "S1"/"S2"
    const GeometryKind kind = blas == 0 ? GeometryKind(pick(2)) : shared_kind[blas - 1];
    GeometryDesc d = kind == GeometryKind::triangles ? GeometryDesc::triangles(tri, {}) : GeometryDesc::procedural({Aabb{}}, {});
    d.instances = translations(pick(5), float(g));
    if (blas != 0) {
      d.blas = "S" + std::to_string(blas);
      // Instances belong to the BLAS: the first member declares them, the others inherit.
      for (const Blas& b : s.blases()) {
        if (b.name == d.blas) d.instances.clear();
      }
    }
    m_geometries.push_back(s.add_geometry("geometry" + std::to_string(g), std::move(d)));
  }
}

// compile() derives each shader's record block, so one shader takes one record type: the
// entries of hit groups tri<h> and proc<h> (shaders chit<h>, isect<h>) carry no data or, for
// h = 0, 1, 2, Args4, Args16 or Args40. Record sizes still vary within a scene.
void RandomScene::plan(Key key, bool is_default, std::uint32_t kind) {
  const std::uint32_t h = pick(3);
  const std::uint32_t size_class = pick(4) == 0 ? 0 : h + 1;
  m_plan.push_back({key, is_default, m_groups[kind][h].index(), size_class, m_tag++});
}

/// Plans the bindings, then shuffles them so they are added in a random order.
void RandomScene::plan_bindings() {
  std::array<std::vector<bool>, 2> has_default{std::vector<bool>(m_ray_count), std::vector<bool>(m_ray_count)};
  for (std::uint32_t k = 0; k < 2; ++k) {
    for (std::uint32_t r = 0; r < m_ray_count; ++r) {
      if (pick(3) == 0) {
        has_default[k][r] = true;
        plan({r, no_index, no_index}, true, k);
      }
    }
  }
  for (GeometryId g : m_geometries) {
    const auto kind = static_cast<std::uint32_t>(m_scene.geometry(g).desc.kind);
    const auto instances = static_cast<std::uint32_t>(m_scene.blas_of(g).instances.size());
    for (std::uint32_t r = 0; r < m_ray_count; ++r) {
      const std::uint32_t mode = pick(4);
      const bool wide = mode == 0 || mode == 1 || (mode == 3 && !has_default[kind][r]);
      if (wide) plan({r, g.index(), no_index}, false, kind);
      for (std::uint32_t i = 0; i < instances; ++i) {
        if (mode == 2 || (mode == 1 && pick(2) == 0)) plan({r, g.index(), i}, false, kind);
      }
    }
  }
  std::shuffle(m_plan.begin(), m_plan.end(), m_rng);
}

/// The entries, added after every entity.
void RandomScene::add_bindings() {
  m_scene.add_raygen("rgen");
  if (pick(2)) m_scene.add_miss(m_rays[0], m_sig4, Args4{0xABCDu});
  m_default_tag = {std::vector<std::uint32_t>(m_ray_count, 0), std::vector<std::uint32_t>(m_ray_count, 0)};
  for (const Planned& p : m_plan) add_binding(p);
}

void RandomScene::add_binding(const Planned& p) {
  TestScene& t = m_scene;
  const HitGroupId group(p.group);
  const RayId<TestPayload> ray = m_rays[p.key.ray];
  const GeometryId geometry(p.key.geometry);
  const std::uint32_t instance = p.key.instance == no_index ? all_instances : p.key.instance;
  EntryId id;
  if (p.is_default) {
    switch (p.size_class) {
      case 0: id = t.set_default_hit(ray, group); break;
      case 1: id = t.set_default_hit(ray, group, m_sig4, Args4{p.tag}); break;
      case 2: id = t.set_default_hit(ray, group, m_sig16, Args16{p.tag, {}}); break;
      default: id = t.set_default_hit(ray, group, m_sig40, Args40{p.tag, {}}); break;
    }
    m_default_tag[static_cast<std::uint32_t>(t.hit_group(group).desc.kind)][p.key.ray] = p.tag;
  } else {
    switch (p.size_class) {
      case 0: id = t.add_hit(ray, group, geometry, instance); break;
      case 1: id = t.add_hit(ray, group, m_sig4, Args4{p.tag}, geometry, instance); break;
      case 2: id = t.add_hit(ray, group, m_sig16, Args16{p.tag, {}}, geometry, instance); break;
      default: id = t.add_hit(ray, group, m_sig40, Args40{p.tag, {}}, geometry, instance); break;
    }
    (p.key.instance == no_index ? m_wide_tag : m_specific_tag)[p.key] = p.tag;
  }
  m_entry_of_tag[p.tag] = id.index();
}

/// The oracle: instance-specific, else geometry-wide, else the ray's default for the kind.
std::uint32_t RandomScene::expected_tag(std::uint32_t r, GeometryId g, std::uint32_t i, std::uint32_t kind) const {
  if (auto it = m_specific_tag.find({r, g.index(), i}); it != m_specific_tag.end()) return it->second;
  if (auto w = m_wide_tag.find({r, g.index(), no_index}); w != m_wide_tag.end()) return w->second;
  return m_default_tag[kind][r];
}

std::uint64_t RandomScene::check() const {
  const TestScene& s = m_scene;
  const auto all = all_limits();
  const auto limits = all[m_seed % all.size()];
  const Plan sbt = compile(s);
  const SbtLayout layout = sbt.layout(limits);
  const auto hit = sbt.records(SbtRegionKind::hit);
  std::vector<std::byte> buffer(layout.size);
  sbt.write(layout, buffer, fake_handles(sbt, layout));
  std::vector<bool> reached(hit.size(), false);
  std::uint64_t checked = 0;
  for (GeometryId g : m_geometries) {
    const Blas& blas = s.blas_of(g);
    for (std::uint32_t i = 0; i < blas.instances.size(); ++i) {
      for (std::uint32_t r = 0; r < m_ray_count; ++r) {
        const std::uint32_t tag = expected_tag(r, g, i, static_cast<std::uint32_t>(blas.kind));
        REQUIRE(tag != 0);
        const Entry& expected = s.entries().all()[m_entry_of_tag.at(tag)];
        // The Vulkan rule, computed from what the TLAS instance and BLAS carry.
        const TlasInstance& inst = sbt.instances()[sbt.tlas_index(g, i)];
        CHECK(inst.blas == s.geometry(g).blas);
        CHECK(inst.instance == i);
        const std::uint32_t record = inst.sbt_offset + s.geometry(g).geometry_index * m_ray_count + r;
        REQUIRE(record < hit.size());
        CHECK(hit[record].entry == m_entry_of_tag.at(tag));
        const HitResolution res = sbt.resolve(m_rays[r], g, i);
        CHECK(res.record == record);
        CHECK(*res.entry == expected);
        CHECK(sbt.pipeline().groups[hit[record].group].hit_group.index() == expected.hit_group);
        // The bytes the GPU reads at that record: the handle of the bound group, then its data.
        const std::uint64_t at = layout.record_offset(SbtRegionKind::hit, record);
        CHECK(buffer[at] == std::byte(hit[record].group + 1));
        if (!s.entries().data(expected).empty()) {
          std::uint32_t written = 0;
          std::memcpy(&written, buffer.data() + at + limits.sbt.handle_size, 4);
          CHECK(written == tag);
        }
        reached[record] = true;
        ++checked;
      }
    }
  }
  // No record is unreachable: the table holds no more than the scene needs.
  CHECK(std::count(reached.begin(), reached.end(), false) == 0);
  check_layout_invariants(layout, {{{1, sbt.pipeline().max_root_arguments_size[0]},
                                    {m_ray_count, sbt.pipeline().max_root_arguments_size[1]},
                                    {static_cast<std::uint32_t>(hit.size()), sbt.pipeline().max_root_arguments_size[2]},
                                    {}}});
  return checked;
}

}  // namespace

TEST_CASE("compile 1000 random scenes resolve every ray geometry and instance to its entry") {
  std::uint64_t checked = 0;
  for (std::uint32_t seed = 0; seed < 1000; ++seed) {
    INFO("seed " << seed);
    checked += RandomScene(seed).check();
  }
  CHECK(checked > 10000);
}

TEST_CASE("compile missing pairs are listed unless a default entry exists") {
  ReportScene r;
  build_report_scene(r);
  auto& t = r.scene;
  t.add_raygen("Raygen");
  const auto sig = r.scene.local_signature_id<TriangleRootArguments>("Triangle");
  t.add_hit(r.radiance, r.scene.hit_group_id("Triangle"), sig, TriangleRootArguments{}, r.plane);
  t.add_hit(r.radiance, r.scene.hit_group_id("Julia"), r.julia);
  t.add_hit(r.shadow, r.scene.hit_group_id("Julia_Shadow"), r.julia, 1);
  CHECK_THROWS_WITH_AS(compile(t),
                       doctest::Contains("compile: 6 hit records have no entry (ray, geometry, instance): "
                                         "(\"Shadow\", \"GlobalGeometry\", instances without own entries)"),
                       MissingEntryError);
  CHECK_THROWS_WITH_AS(compile(t), doctest::Contains("(\"Shadow\", \"Julia\", instances without own entries)"),
                       MissingEntryError);
  CHECK_THROWS_WITH_AS(compile(t), doctest::Contains("(\"Radiance\", \"Pacman\""), MissingEntryError);
  CHECK_THROWS_WITH_AS(compile(t), doctest::Contains("add them with Scene::add_hit or declare Scene::set_default_hit"),
                       MissingEntryError);
  t.set_default_hit(r.shadow, r.scene.hit_group_id("Triangle_Shadow"));
  t.set_default_hit(r.shadow, r.scene.hit_group_id("Pacman_Shadow"));
  t.set_default_hit(r.radiance, r.scene.hit_group_id("Pacman"));
  const Plan sbt = compile(t);
  CHECK(r.scene.hit_groups().name(sbt.resolve(r.shadow, r.mandelbulb, 0).entry->hit_group) == "Pacman_Shadow");
  CHECK(r.scene.hit_groups().name(sbt.resolve(r.shadow, r.julia, 1).entry->hit_group) == "Julia_Shadow");
  CHECK(r.scene.hit_groups().name(sbt.resolve(r.shadow, r.julia, 0).entry->hit_group) == "Pacman_Shadow");
  CHECK(r.scene.hit_groups().name(sbt.resolve(r.shadow, r.plane, 0).entry->hit_group) == "Triangle_Shadow");
  CHECK_THROWS_WITH_AS(t.set_default_hit(r.shadow, r.scene.hit_group_id("Julia_Shadow")),
                       doctest::Contains("Scene::set_default_hit: ray \"Shadow\" already has a default procedural hit group"),
                       DuplicateIdError);
}

TEST_CASE("compile duplicate bindings name both entries") {
  ReportScene r;
  build_report_scene(r);
  add_report_entries(r);
  const auto sig = r.scene.local_signature_id<ProceduralRootArguments>("Procedural");
  r.scene.add_hit(r.radiance, r.scene.hit_group_id("Pacman"), sig, ProceduralRootArguments{}, r.pacman, 1);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("compile: entries #"), DuplicateIdError);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("both bind ray \"Radiance\" on instance 1 of geometry \"Pacman\""),
                       DuplicateIdError);
  ReportScene u;
  build_report_scene(u);
  add_report_entries(u);
  u.scene.add_hit(u.shadow, u.scene.hit_group_id("Triangle_Shadow"), u.plane);
  CHECK_THROWS_WITH_AS(compile(u.scene), doctest::Contains("on all instances of geometry \"GlobalGeometry\""),
                       DuplicateIdError);
  ReportScene w;
  build_report_scene(w);
  auto& v = w.scene;
  const auto w_sig = v.local_signature_id<ProceduralRootArguments>("Procedural");  // sig is r's: another scene
  v.add_miss(w.radiance, w_sig, ProceduralRootArguments{});
  CHECK_THROWS_WITH_AS(v.add_miss(w.radiance, w_sig, ProceduralRootArguments{}),
                       doctest::Contains("Scene::add_miss: ray \"Radiance\" already has a miss entry"),
                       DuplicateIdError);
}

TEST_CASE("compile one block per BLAS and the instance limit") {
  TestScene s;
  const auto ray = s.add_ray<TestPayload>("r", {.miss = "m"});
  const auto group = s.add_hit_group("g", {.closest_hit = "c"});
  TriangleMesh tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}};
  // Three one-instance BLASes: offsets 0, 1, 2; a device allowing 2 instances refuses the scene.
  std::vector<GeometryId> geometries;
  for (const char* name : {"g0", "g1", "g2"}) geometries.push_back(s.add_geometry(name, GeometryDesc::triangles(tri)));
  s.add_raygen("rgen");
  for (GeometryId g : geometries) s.add_hit(ray, group, g);
  const Plan plan = compile(s);
  CHECK(plan.instance_sbt_offset(s.geometry_id("g2"), 0) == 2);
  DeviceLimits limits = lavapipe_limits;
  limits.max_instance_count = 2;
  CHECK_THROWS_AS(plan.layout(limits), DeviceLimitError);
}

TEST_CASE("compile refuses a scene without a raygen entry") {
  ReportScene r;
  build_report_scene(r);
  CHECK_THROWS_WITH_AS(compile(r.scene), doctest::Contains("compile: no raygen entry; add one with Scene::add_raygen"),
                       SceneError);
  r.scene.add_raygen("Raygen");
  CHECK_THROWS_AS(compile(r.scene), MissingEntryError);  // the next check: the hit records
}

TEST_CASE("compile keeps a BLAS's shared block for instances added at run time only when asked") {
  TestScene s;
  const auto ray = s.add_ray<TestPayload>("r", {.miss = "m"});
  const auto group = s.add_hit_group("g", {.closest_hit = "c"});
  const auto own = s.add_hit_group("own", {.closest_hit = "own"});
  TriangleMesh tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}};
  GeometryDesc desc = GeometryDesc::triangles(tri);  // one instance, with an entry of its own
  const GeometryId fixed = s.add_geometry("fixed", desc);
  desc.may_add_instances = true;
  const GeometryId open = s.add_geometry("open", desc);
  desc.instances.clear();  // none declared: only added ones will use its records
  const GeometryId later = s.add_geometry("later", desc);
  s.add_raygen("rgen");
  for (GeometryId g : {fixed, open}) s.add_hit(ray, own, g, 0);
  TestScene missing = s;  // `open` and `later` asked for shared records but have no entry for them
  CHECK_THROWS_WITH_AS(compile(missing), doctest::Contains("(\"r\", \"open\", instances without own entries)"),
                       MissingEntryError);
  CHECK_THROWS_WITH_AS(compile(missing), doctest::Contains("(\"r\", \"later\", instances without own entries)"),
                       MissingEntryError);
  s.set_default_hit(ray, group);
  const Plan plan = compile(s);
  const auto blas_of = [&](GeometryId g) { return plan.blases()[plan.geometry(g).blas]; };
  CHECK(blas_of(fixed).shared_sbt_offset == no_index);  // not asked, and no instance shares: no block
  const std::uint32_t open_shared = blas_of(open).shared_sbt_offset;
  REQUIRE(open_shared != no_index);
  CHECK(open_shared != plan.instance_sbt_offset(open, 0));  // its instance keeps its own records
  CHECK(blas_of(later).shared_sbt_offset != no_index);
  CHECK(blas_of(later).instance_count == 0);
  const auto records = plan.records(SbtRegionKind::hit);
  REQUIRE(open_shared < records.size());
  CHECK(records[open_shared].entry != no_index);
  CHECK(s.hit_groups().name(s.entries().all()[records[open_shared].entry].hit_group) == "g");  // the default
}
