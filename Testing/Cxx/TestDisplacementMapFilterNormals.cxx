// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter's normals and arrays: Mesh normals and fits independent of the point
// numbering, slopes of the interpolants, area weights, tangents, arrays passed through,
// output precision.

#include "DisplacementFilterTestHelpers.h"

namespace
{
// @a mesh (MakeMesh's triangle pairs) as quads.
vtkSmartPointer<vtkPolyData> AsQuads(vtkPolyData* mesh)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(mesh);
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkIdList> t0, t1;
  for (vtkIdType c = 0; c + 1 < mesh->GetNumberOfCells(); c += 2)
  {
    // (a, b, d) and (a, d, c) -> (a, b, d, c)
    mesh->GetCellPoints(c, t0);
    mesh->GetCellPoints(c + 1, t1);
    const vtkIdType q[4] = { t0->GetId(0), t0->GetId(1), t0->GetId(2), t1->GetId(2) };
    quads->InsertNextCell(4, q);
  }
  out->SetPolys(quads);
  return out;
}

// Points, normals and tangents of @a y are those of @a x bit for bit, point i of @a x against
// point perm[i] of @a y (the same point without @a perm).
void ExpectSameOutputBits(vtkPolyData* x, vtkPolyData* y, const std::string& what,
  const std::vector<vtkIdType>* perm = nullptr)
{
  for (const char* name : { "", "Normals", "Tangents" })
  {
    vtkDataArray* u = *name ? x->GetPointData()->GetArray(name) : x->GetPoints()->GetData();
    vtkDataArray* v = *name ? y->GetPointData()->GetArray(name) : y->GetPoints()->GetData();
    ASSERT_TRUE(u && v) << name << " " << what;
    ASSERT_EQ(u->GetNumberOfValues(), v->GetNumberOfValues()) << name << " " << what;
    const size_t bytes = static_cast<size_t>(u->GetDataTypeSize()) * u->GetNumberOfComponents();
    const auto* pu = static_cast<const unsigned char*>(u->GetVoidPointer(0));
    const auto* pv = static_cast<const unsigned char*>(v->GetVoidPointer(0));
    vtkIdType differ = 0;
    for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
    {
      differ += std::memcmp(pu + bytes * i, pv + bytes * (perm ? (*perm)[i] : i), bytes) != 0;
    }
    EXPECT_EQ(differ, 0) << (*name ? name : "Points") << " " << what;
  }
}
}

// Mesh normals sum each point's polygons in one order of the polygons: renumbering the points
// (polygons in the same order) must give every point the bits it had, at 1 and 2 threads, on
// first and later executions, with triangles and quads.
TEST(DisplacementMapFilter, MeshNormalsDoNotDependOnPointNumbering)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  for (bool floatPoints : { false, true })
  {
    for (bool quads : { false, true })
    {
      auto mesh = MakeMesh(s, 256, 128, false, floatPoints);
      // Points that need a fallback (a zero normal, a tangent along its normal).
      vtkPointData* pd = mesh->GetPointData();
      pd->GetNormals()->SetTuple3(16383, 0.0, 0.0, 0.0);
      double n[3];
      pd->GetNormals()->GetTuple(16384, n);
      pd->GetTangents()->SetTuple3(16384, n[0], n[1], n[2]);
      if (quads)
      {
        mesh = AsQuads(mesh);
      }
      const std::vector<vtkIdType> perm = RenumberedPoints::RandomIds(mesh->GetNumberOfPoints(), 5);
      auto renumbered = RenumberedPoints::Moved(mesh, perm, mesh->GetNumberOfPoints());
      std::vector<vtkSmartPointer<vtkPolyData>> outputs;
      for (int threads : { 1, 2 })
      {
        vtkSMPTools::Initialize(threads);
        for (vtkPolyData* input : { mesh.GetPointer(), renumbered.GetPointer() })
        {
          vtkNew<vtkDisplacementMapFilter> f;
          f->SetInputData(0, input);
          f->SetInputData(1, image);
          f->SetNormalModeToMesh();
          f->SetInterpolationToCubic();
          f->MergeSeamsOff();
          f->SetMidlevel(0.5);
          for (double scale : { 0.1, 0.2 })
          {
            f->SetScaleFactor(scale);
            f->Update();
            auto out = vtkSmartPointer<vtkPolyData>::New();
            out->DeepCopy(f->GetOutput());
            outputs.push_back(out);
          }
        }
      }
      // outputs: (threads, input, scale)
      for (size_t k = 0; k < outputs.size(); ++k)
      {
        const size_t same = k % 2;
        for (const char* name : { "", "Normals", "Tangents" })
        {
          vtkDataArray* x = *name ? outputs[same]->GetPointData()->GetArray(name)
                                  : outputs[same]->GetPoints()->GetData();
          vtkDataArray* y =
            *name ? outputs[k]->GetPointData()->GetArray(name) : outputs[k]->GetPoints()->GetData();
          ASSERT_TRUE(x && y);
          // The renumbered mesh's point perm[i] against the original's point i.
          const bool moved = (k / 2) % 2 == 1;
          const int nc = x->GetNumberOfComponents();
          const size_t bytes = static_cast<size_t>(x->GetDataTypeSize()) * nc;
          size_t differ = 0;
          for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
          {
            const vtkIdType j = moved ? perm[i] : i;
            differ += std::memcmp(static_cast<const char*>(x->GetVoidPointer(0)) + bytes * i,
                        static_cast<const char*>(y->GetVoidPointer(0)) + bytes * j, bytes) != 0;
          }
          EXPECT_EQ(differ, 0u) << (*name ? name : "Points") << " output " << k << " float "
                                << floatPoints << " quads " << quads;
        }
        EXPECT_TRUE(AllFinite(outputs[k]));
      }
    }
  }
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

// A triangle of zero area has a zero normal and adds nothing to an area-weighted sum (nor to the
// seam test: its corners' neighbours cancel), so a torus with pairs of them, (a, b, a) and
// (a, a, c), inserted after every seventh polygon must give every output of the torus without
// them, bit for bit: with triangles only and with quads among the later polygons, at 1 and 2
// threads, on first executions and on re-executions.
TEST(DisplacementMapFilter, DegenerateTrianglePairsAddNothingToMeshNormals)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  for (bool quads : { false, true })
  {
    auto grid = MakeMesh(s, 256, 128, false, true);
    vtkCellArray* tris = grid->GetPolys();
    const vtkIdType nTris = tris->GetNumberOfCells();
    // The reference's polygons (with quads: every fifth fan pair of the second half merged into
    // the quad (a, b, d, c)) and the same with the degenerate pairs.
    vtkNew<vtkCellArray> plain, withPairs;
    vtkNew<vtkIdList> t0, t1;
    vtkIdType emitted = 0, degenerate = 0;
    auto emit = [&](vtkIdType n, const vtkIdType* ids)
    {
      plain->InsertNextCell(n, ids);
      withPairs->InsertNextCell(n, ids);
      if (++emitted % 7 == 0)
      {
        const vtkIdType a = ids[0], b = ids[1], c = ids[2];
        const vtkIdType first[3] = { a, b, a }, second[3] = { a, a, c };
        withPairs->InsertNextCell(3, first);
        withPairs->InsertNextCell(3, second);
        ++degenerate;
      }
    };
    for (vtkIdType c = 0; c < nTris; c += 2)
    {
      tris->GetCellAtId(c, t0);
      tris->GetCellAtId(c + 1, t1);
      if (quads && c >= nTris / 2 && (c / 2) % 5 == 0)
      {
        const vtkIdType quad[4] = { t0->GetId(0), t0->GetId(1), t0->GetId(2), t1->GetId(2) };
        emit(4, quad);
        continue;
      }
      emit(3, t0->GetPointer(0));
      emit(3, t1->GetPointer(0));
    }
    ASSERT_GT(degenerate, 1000);
    vtkNew<vtkPolyData> reference, augmented;
    reference->ShallowCopy(grid);
    reference->SetPolys(plain);
    augmented->ShallowCopy(grid);
    augmented->SetPolys(withPairs);
    for (int threads : { 1, 2 })
    {
      vtkSMPTools::Initialize(threads);
      vtkNew<vtkDisplacementMapFilter> a, b;
      for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
      {
        f->SetInputData(0, f == a.Get() ? reference.Get() : augmented.Get());
        f->SetInputData(1, image);
        f->SetNormalModeToMesh();
        f->SetMidlevel(0.5);
      }
      for (double scale : { 0.1, 0.25 })
      {
        for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
        {
          f->SetScaleFactor(scale);
          f->Update();
        }
        ExpectSameOutputBits(a->GetOutput(), b->GetOutput(),
          "quads " + std::to_string(quads) + " threads " + std::to_string(threads) + " scale " +
            std::to_string(scale));
        EXPECT_TRUE(AllFinite(b->GetOutput()));
      }
    }
    // The fits count a pair's neighbours whatever its area, so with Exact the pairs matter; the
    // points renumbered (the polygons in the same order) must give every point the bits it had,
    // with Exact as with Mesh. Seams not merged: their means add the members in id order.
    const std::vector<vtkIdType> perm =
      RenumberedPoints::RandomIds(augmented->GetNumberOfPoints(), 7);
    auto renumbered = RenumberedPoints::Moved(augmented, perm, augmented->GetNumberOfPoints());
    for (int mode : { vtkDisplacementMapFilter::Exact, vtkDisplacementMapFilter::Mesh })
    {
      for (int threads : { 1, 2 })
      {
        vtkSMPTools::Initialize(threads);
        vtkNew<vtkDisplacementMapFilter> a, b;
        for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
        {
          f->SetInputData(0, f == a.Get() ? augmented.Get() : renumbered.Get());
          f->SetInputData(1, image);
          f->SetNormalMode(mode);
          f->SetMidlevel(0.5);
          f->SetScaleFactor(0.1);
          f->MergeSeamsOff();
          f->Update();
        }
        ExpectSameOutputBits(a->GetOutput(), b->GetOutput(),
          "mode " + std::to_string(mode) + " quads " + std::to_string(quads) + " threads " +
            std::to_string(threads),
          &perm);
        EXPECT_TRUE(AllFinite(a->GetOutput()));
      }
    }
  }
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

#ifdef __linux__
// A polygon with no points, last in the list, must not be read: its connectivity ends where the
// memory does (a guard page after it), and an empty polygon adds nothing, so every output is the
// same without it, bit for bit (the points renumbered, so that no point's polygons are near it).
TEST(DisplacementMapFilter, EmptyLastPolygonIsNotRead)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  auto grid = MakeMesh(s, 256, 128, false, true);
  auto mesh = RenumberedPoints::Moved(
    grid, RenumberedPoints::RandomIds(grid->GetNumberOfPoints(), 9), grid->GetNumberOfPoints());
  vtkDataArray* offsets = mesh->GetPolys()->GetOffsetsArray();
  vtkDataArray* connectivity = mesh->GetPolys()->GetConnectivityArray();
  const vtkIdType nCells = mesh->GetPolys()->GetNumberOfCells();
  const vtkIdType nConn = connectivity->GetNumberOfValues();
  const size_t page = static_cast<size_t>(sysconf(_SC_PAGESIZE));
  const size_t bytes = (nConn * sizeof(vtkIdType) + page - 1) / page * page;
  void* memory =
    mmap(nullptr, bytes + page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(memory, MAP_FAILED);
  ASSERT_EQ(mprotect(static_cast<char*>(memory) + bytes, page, PROT_NONE), 0);
  {
    vtkIdType* conn = reinterpret_cast<vtkIdType*>(static_cast<char*>(memory) + bytes) - nConn;
    for (vtkIdType k = 0; k < nConn; ++k)
    {
      conn[k] = static_cast<vtkIdType>(connectivity->GetComponent(k, 0));
    }
    vtkNew<vtkIdTypeArray> guardedOffsets, guardedConn;
    guardedOffsets->SetNumberOfValues(nCells + 2);
    for (vtkIdType c = 0; c <= nCells; ++c)
    {
      guardedOffsets->SetValue(c, static_cast<vtkIdType>(offsets->GetComponent(c, 0)));
    }
    guardedOffsets->SetValue(nCells + 1, nConn); // the empty polygon
    guardedConn->SetArray(conn, nConn, 1);
    vtkNew<vtkCellArray> polys;
    polys->SetData(guardedOffsets, guardedConn);
    vtkNew<vtkPolyData> withEmpty;
    withEmpty->ShallowCopy(mesh);
    withEmpty->SetPolys(polys);
    for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
           vtkDisplacementMapFilter::Mesh })
    {
      vtkNew<vtkDisplacementMapFilter> a, b;
      for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
      {
        f->SetInputData(0, f == a.Get() ? mesh.Get() : withEmpty.Get());
        f->SetInputData(1, image);
        f->SetNormalMode(mode);
        f->SetScaleFactor(0.1);
        f->Update();
      }
      ExpectSameOutputBits(a->GetOutput(), b->GetOutput(), "mode " + std::to_string(mode));
    }
  }
  munmap(memory, bytes + page);
}
#endif

namespace
{
// @a mesh (MakeMesh's) with the triangle pairs of its first row made quads and one triangle made
// degenerate (a corner named twice), so that the fits meet polygons that are not three distinct
// points.
vtkSmartPointer<vtkPolyData> WithOddPolygons(vtkPolyData* mesh, int U)
{
  auto odd = vtkSmartPointer<vtkPolyData>::New();
  odd->ShallowCopy(mesh);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> a, b;
  const vtkIdType cells = mesh->GetNumberOfCells();
  for (vtkIdType c = 0; c < cells; ++c)
  {
    mesh->GetCellPoints(c, a);
    if (c < 2 * U && c % 2 == 0)
    {
      // (a, b, d) and (a, d, c): the quad (a, b, d, c).
      mesh->GetCellPoints(c + 1, b);
      const vtkIdType quad[4] = { a->GetId(0), a->GetId(1), a->GetId(2), b->GetId(2) };
      polys->InsertNextCell(4, quad);
      ++c;
      continue;
    }
    if (c == cells / 2 + 7)
    {
      a->SetId(2, a->GetId(0));
    }
    polys->InsertNextCell(a);
  }
  odd->SetPolys(polys);
  return odd;
}

}

// The fits (Exact; Approximate without dPdu/dPdv) add each point's neighbours in one order of the
// polygons. Renumbering the points (polygons in the same order) must give every point the bits it
// had: float and double arrays, with and without dPdu/dPdv, at 1 and 2 threads, on first and later
// executions, with quads and a degenerate triangle (seams not merged: their means add the members
// in id order), and with points that need a fallback (a zero normal, a tangent along the normal).
TEST(DisplacementMapFilter, FitsDoNotDependOnPointNumbering)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  const int U = 256, V = 128;
  for (bool floatPoints : { false, true })
  {
    for (bool derivatives : { false, true })
    {
      auto mesh = WithOddPolygons(MakeMesh(s, U, V, derivatives, floatPoints), U);
      const vtkIdType count = mesh->GetNumberOfPoints();
      ASSERT_GT(count, 2 * 16384);
      vtkPointData* pd = mesh->GetPointData();
      pd->GetNormals()->SetTuple3(16384 + 3, 0.0, 0.0, 0.0);
      double n[3];
      pd->GetNormals()->GetTuple(16384 - 2, n);
      pd->GetTangents()->SetTuple3(16384 - 2, n[0], n[1], n[2]);
      const std::vector<vtkIdType> perm = RenumberedPoints::RandomIds(mesh->GetNumberOfPoints(), 5);
      auto renumbered = RenumberedPoints::Moved(mesh, perm, mesh->GetNumberOfPoints());
      for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
      {
        for (int threads : { 1, 2 })
        {
          vtkSMPTools::Initialize(threads);
          vtkNew<vtkDisplacementMapFilter> a, b;
          for (vtkDisplacementMapFilter* f : { a.Get(), b.Get() })
          {
            f->SetInputData(0, f == a.Get() ? mesh : renumbered);
            f->SetInputData(1, image);
            f->SetNormalMode(mode);
            f->SetScaleFactor(0.1);
            f->SetMidlevel(0.5);
            f->SetInterpolation(vtkDisplacementMapFilter::Cubic);
            // The seam groups' means add their members in id order, which renumbering changes.
            f->MergeSeamsOff();
          }
          for (int execution = 0; execution < 2; ++execution)
          {
            const std::string what = std::string(floatPoints ? "float" : "double") +
              (derivatives ? " dPdu/dPdv" : "") + " mode " + std::to_string(mode) + " threads " +
              std::to_string(threads) + " execution " + std::to_string(execution);
            a->SetScaleFactor(0.1 + 0.05 * execution);
            b->SetScaleFactor(0.1 + 0.05 * execution);
            a->Update();
            b->Update();
            vtkPolyData* x = a->GetOutput();
            vtkPolyData* y = b->GetOutput();
            vtkIdType differ = 0;
            for (const char* name : { "", "Normals", "Tangents" })
            {
              vtkDataArray* ax =
                *name ? x->GetPointData()->GetArray(name) : x->GetPoints()->GetData();
              vtkDataArray* ay =
                *name ? y->GetPointData()->GetArray(name) : y->GetPoints()->GetData();
              ASSERT_TRUE(ax && ay) << name << " " << what;
              const size_t bytes =
                static_cast<size_t>(ax->GetDataTypeSize()) * ax->GetNumberOfComponents();
              const auto* px = static_cast<const unsigned char*>(ax->GetVoidPointer(0));
              const auto* py = static_cast<const unsigned char*>(ay->GetVoidPointer(0));
              for (vtkIdType i = 0; i < count; ++i)
              {
                differ += std::memcmp(px + bytes * i, py + bytes * perm[i], bytes) != 0;
              }
            }
            EXPECT_EQ(differ, 0) << what;
            EXPECT_TRUE(AllFinite(x)) << what;
          }
        }
      }
    }
  }
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

namespace
{
// Catmull-Rom through p0..p3 at the fraction f of the way from p1 to p2: the value and its
// derivative in f, from the spline's polynomial form (the cardinal spline of tension 1/2),
// written independently of the filter's weights.
std::array<double, 2> CatmullRomSpline(double p0, double p1, double p2, double p3, double f)
{
  const double a = -p0 + 3 * p1 - 3 * p2 + p3, b = 2 * p0 - 5 * p1 + 4 * p2 - p3, c = p2 - p0;
  return { 0.5 * (((a * f + b) * f + c) * f + 2 * p1), 0.5 * ((3 * a * f + 2 * b) * f + c) };
}

// The bicubic Catmull-Rom interpolant through the texel centres, each of its 4x4 texels
// wrapped by GLWrap (as GLLinear wraps its 2x2): height and its derivatives in s and t.
std::array<double, 3> RefCubic(const float* img, int W, int H, int mode, double s, double t)
{
  const double u = s * W - 0.5, v = t * H - 0.5;
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  const double fx = u - std::floor(u), fy = v - std::floor(v);
  auto T = [&](int i, int j) { return GLTexel(img, W, H, mode, i, j); };
  double row[4], drow[4];
  for (int l = 0; l < 4; ++l)
  {
    const int j = j0 - 1 + l;
    const auto r = CatmullRomSpline(T(i0 - 1, j), T(i0, j), T(i0 + 1, j), T(i0 + 2, j), fx);
    row[l] = r[0];
    drow[l] = r[1];
  }
  const auto h = CatmullRomSpline(row[0], row[1], row[2], row[3], fy);
  const auto hs = CatmullRomSpline(drow[0], drow[1], drow[2], drow[3], fy);
  return { h[0], W * hs[0], H * h[1] };
}

// GLLinear with its derivatives: within the 2x2 texels around (s,t) the bilinear form's
// slope, which jumps where (s,t) crosses a row or column of texel centres.
std::array<double, 3> RefLinear(const float* img, int W, int H, int mode, double s, double t)
{
  const double u = s * W - 0.5, v = t * H - 0.5;
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  const double a = u - std::floor(u), b = v - std::floor(v);
  auto T = [&](int i, int j) { return GLTexel(img, W, H, mode, i, j); };
  const double t00 = T(i0, j0), t10 = T(i0 + 1, j0), t01 = T(i0, j0 + 1), t11 = T(i0 + 1, j0 + 1);
  return { GLLinear(img, W, H, mode, s, t), W * ((1 - b) * (t10 - t00) + b * (t11 - t01)),
    H * ((1 - a) * (t01 - t00) + a * (t11 - t10)) };
}
} // namespace

// Every interpolant's slope, not only its height: on the flat probes (normal +z, P_s = +x,
// P_t = +y) Approximate's normal of z = Scale h is (-Scale h_s, -Scale h_t, 1), which must
// equal the references' analytic derivatives in every wrap mode, inside and outside [0,1],
// Cubic across the borders included. Probes a millionth of a texel either side of the texel
// centres, where Linear's slope jumps, tell the interpolant's own derivative from a central
// difference with a fixed epsilon, which would blur the jump into a mean of the two slopes.
TEST(DisplacementMapFilter, SlopesMatchTheInterpolants)
{
  const int W = 7, H = 5;
  auto image = RandomImage(W, H, 3);
  const float* img = static_cast<float*>(image->GetScalarPointer());
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(17);
  std::vector<std::array<double, 2>> st = RandomCoordinates(random, 300);
  for (int i = -1; i <= W; ++i)
  {
    for (double side : { -1e-6, 1e-6 })
    {
      st.push_back({ (i + 0.5 + side) / W, random->GetNextRangeValue(-0.5, 1.5) });
      st.push_back({ random->GetNextRangeValue(-0.5, 1.5), (i % H + 0.5 + side) / H });
    }
  }
  auto probes = Probes(st);
  const double scale = 0.7;
  for (int wrap : { vtkDisplacementMapFilter::ClampToEdge, vtkDisplacementMapFilter::Repeat,
         vtkDisplacementMapFilter::MirroredRepeat, vtkDisplacementMapFilter::ClampToBorder })
  {
    // The test's own premise: the slope does jump across the texel centres probed.
    double jump = 0.0;
    for (int i = 0; i + 1 < W; ++i)
    {
      const auto left = RefLinear(img, W, H, wrap, (i + 0.5 - 1e-6) / W, 0.3);
      const auto right = RefLinear(img, W, H, wrap, (i + 0.5 + 1e-6) / W, 0.3);
      jump = std::max(jump, std::abs(left[1] - right[1]));
    }
    EXPECT_GT(jump, 1.0);
    for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear,
           vtkDisplacementMapFilter::Cubic })
    {
      auto out =
        Displace(probes, image, vtkDisplacementMapFilter::Approximate, scale, 0.0, interp, wrap);
      double worstHeight = 0.0, worstAngle = 0.0;
      for (size_t k = 0; k < st.size(); ++k)
      {
        const double s = st[k][0], t = st[k][1];
        std::array<double, 3> ref;
        if (interp == vtkDisplacementMapFilter::Nearest)
        {
          ref = { GLNearest(img, W, H, wrap, s, t), 0.0, 0.0 };
        }
        else if (interp == vtkDisplacementMapFilter::Linear)
        {
          ref = RefLinear(img, W, H, wrap, s, t);
        }
        else
        {
          ref = RefCubic(img, W, H, wrap, s, t);
        }
        double p[3], n[3];
        out->GetPoint(static_cast<vtkIdType>(k), p);
        out->GetPointData()->GetNormals()->GetTuple(static_cast<vtkIdType>(k), n);
        worstHeight = std::max(worstHeight, std::abs(p[2] - scale * ref[0]));
        worstAngle = std::max(worstAngle,
          AngleDeg({ n[0], n[1], n[2] }, Unit({ -scale * ref[1], -scale * ref[2], 1.0 })));
      }
      EXPECT_LT(worstHeight, 1e-12) << "wrap " << wrap << " interp " << interp;
      EXPECT_LT(worstAngle, 1e-9) << "wrap " << wrap << " interp " << interp;
    }
  }
}

// Mesh normals are area-weighted: on a grid whose interior points are moved at random within
// their cells (the texture coordinates with them), so that the triangles around a point differ
// in area and a few are even turned over, each output normal equals the normalised sum of the
// cross products of the displaced triangles around it, computed here from the output points,
// each triangle oriented as its corners' input normals (the sign of its input cross product
// against their sum). The same mesh's mean of unit triangle normals (vtkPolyDataNormals'
// weighting) differs from it by far more than the tolerance, so the test tells them apart.
TEST(DisplacementMapFilter, MeshNormalsAreAreaWeighted)
{
  const int U = 12;
  const Surface s = Rectangle(0.3);
  auto mesh = MakeMesh(s, U, U, false);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(29);
  vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
  for (int j = 1; j < U; ++j)
  {
    for (int i = 1; i < U; ++i)
    {
      const vtkIdType id = static_cast<vtkIdType>(j) * (U + 1) + i;
      const double u = (i + random->GetNextRangeValue(-0.35, 0.35)) / U;
      const double v = (j + random->GetNextRangeValue(-0.35, 0.35)) / U;
      const Vec p = s.P(u, v);
      mesh->GetPoints()->SetPoint(id, p.data());
      tc->SetTuple2(id, u, v);
    }
  }
  auto out = Displace(mesh, MakeHeightImage(s.Height, 64, 64), vtkDisplacementMapFilter::Mesh,
    s.Scale, s.Midlevel, vtkDisplacementMapFilter::Linear);
  const vtkIdType n = out->GetNumberOfPoints();
  std::vector<Vec> weighted(n, Vec{ 0, 0, 0 }), unweighted(n, Vec{ 0, 0, 0 });
  vtkCellArray* polys = out->GetPolys();
  vtkDataArray* normalsIn = mesh->GetPointData()->GetNormals();
  vtkNew<vtkIdList> ids;
  int turned = 0;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    ASSERT_EQ(ids->GetNumberOfIds(), 3);
    Vec p[3], q[3], nsum{ 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      out->GetPoint(ids->GetId(k), p[k].data());
      mesh->GetPoint(ids->GetId(k), q[k].data());
      Vec nk;
      normalsIn->GetTuple(ids->GetId(k), nk.data());
      nsum = Add(nsum, nk);
    }
    Vec m = CrossV(Add(p[1], p[0], -1.0), Add(p[2], p[0], -1.0));
    if (DotV(CrossV(Add(q[1], q[0], -1.0), Add(q[2], q[0], -1.0)), nsum) < 0.0)
    {
      m = { -m[0], -m[1], -m[2] };
      ++turned;
    }
    for (int k = 0; k < 3; ++k)
    {
      weighted[ids->GetId(k)] = Add(weighted[ids->GetId(k)], m);
      unweighted[ids->GetId(k)] = Add(unweighted[ids->GetId(k)], Unit(m));
    }
  }
  double worst = 0.0, apart = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    Vec got;
    out->GetPointData()->GetNormals()->GetTuple(i, got.data());
    worst = std::max(worst, AngleDeg(got, weighted[i]));
    apart = std::max(apart, AngleDeg(weighted[i], unweighted[i]));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(apart, 0.5);
  EXPECT_GT(turned, 0); // the orientation rule is exercised
}

// Tangents in every mode that makes new normals: the input tangent with its part along the new
// normal removed and normalised (Gram-Schmidt). A SurfaceDetail frame keeps its handedness
// array (w = +1 or -1) and its mark; tangents from elsewhere (no handedness) get none.
TEST(DisplacementMapFilter, TangentsAreTheInputsOrthogonalised)
{
  const Surface s = Torus(0.15);
  auto image = MakeHeightImage(s.Height, 128, 64);
  for (bool withHandedness : { true, false })
  {
    auto mesh = MakeMesh(s, 32, 16, true);
    auto t4 = TangentFrame(mesh);
    vtkNew<vtkDoubleArray> tin, win;
    tin->SetNumberOfComponents(3);
    tin->SetNumberOfTuples(mesh->GetNumberOfPoints());
    win->SetNumberOfTuples(mesh->GetNumberOfPoints());
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double t[4];
      t4->GetTuple(i, t);
      tin->SetTuple(i, t);
      // Every third point mirrored: w = -1 (a mirrored texture there).
      win->SetValue(i, i % 3 == 1 ? -1.0 : 1.0);
    }
    mesh->GetPointData()->RemoveArray("Tangents");
    mesh->GetPointData()->RemoveArray("TangentHandedness");
    if (withHandedness)
    {
      vtkSurfaceDetailTangents::SetFrame(mesh->GetPointData(), tin, win);
    }
    else
    {
      tin->SetName("VTKTangents");
      mesh->GetPointData()->SetTangents(tin);
    }
    for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
           vtkDisplacementMapFilter::Mesh })
    {
      SCOPED_TRACE(std::string(withHandedness ? "with" : "without") + " handedness, mode " +
        std::to_string(mode));
      auto out = Displace(mesh, image, mode, s.Scale);
      vtkDataArray* t = out->GetPointData()->GetTangents();
      ASSERT_NE(t, nullptr);
      ASSERT_EQ(t->GetNumberOfComponents(), 3);
      EXPECT_STREQ(t->GetName(), tin->GetName());
      EXPECT_EQ(
        t->GetInformation()->Has(vtkSurfaceDetailTangents::WITH_HANDEDNESS()), withHandedness);
      vtkDataArray* w = vtkSurfaceDetailTangents::GetHandedness(out->GetPointData());
      EXPECT_EQ(w != nullptr, withHandedness);
      double worst = 0.0, turned = 0.0;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double nn[3], got[3], in[3];
        out->GetPointData()->GetNormals()->GetTuple(i, nn);
        t->GetTuple(i, got);
        tin->GetTuple(i, in);
        const Vec normal = { nn[0], nn[1], nn[2] }, input = { in[0], in[1], in[2] };
        const Vec expected = Unit(Add(input, normal, -DotV(input, normal)));
        worst = std::max(worst, AngleDeg({ got[0], got[1], got[2] }, expected));
        turned = std::max(turned, AngleDeg(input, expected));
        EXPECT_NEAR(got[0] * got[0] + got[1] * got[1] + got[2] * got[2], 1.0, 1e-12);
        if (w)
        {
          ASSERT_EQ(w->GetComponent(i, 0), win->GetValue(i)) << i;
        }
      }
      EXPECT_LT(worst, 1e-9);
      // The premise: the new normals did turn the tangents, so keeping them would fail.
      EXPECT_GT(turned, 1.0);
    }
  }
}

// Every array but the points, normals and tangents passes through in every mode, bit for bit:
// other point arrays, dPdu and dPdv (they describe the input surface), texture coordinates and
// cell data.
TEST(DisplacementMapFilter, OtherArraysPassThroughInEveryMode)
{
  const Surface s = Torus();
  auto mesh = MakeMesh(s, 16, 8, true, false, true);
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("Temperature");
  vtkNew<vtkIntArray> material;
  material->SetName("Material");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    temperature->InsertNextValue(static_cast<float>(0.5 * i));
  }
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    material->InsertNextValue(static_cast<int>(c % 7));
  }
  mesh->GetPointData()->AddArray(temperature);
  mesh->GetCellData()->AddArray(material);
  auto image = MakeHeightImage(s.Height, 32, 16);
  vtkNew<vtkPolyData> before;
  before->DeepCopy(mesh);
  for (int mode : AllModes)
  {
    SCOPED_TRACE(mode);
    auto out = Displace(mesh, image, mode);
    vtkPointData* pd = out->GetPointData();
    for (const char* name : { "Temperature", "dPdu", "dPdv", "dNdu", "dNdv", "TCoords" })
    {
      ASSERT_NE(pd->GetArray(name), nullptr) << name;
      EXPECT_TRUE(SameBits(pd->GetArray(name), mesh->GetPointData()->GetArray(name))) << name;
    }
    EXPECT_EQ(pd->GetTCoords(), pd->GetArray("TCoords"));
    ASSERT_NE(out->GetCellData()->GetArray("Material"), nullptr);
    EXPECT_TRUE(SameBits(out->GetCellData()->GetArray("Material"), material));
    EXPECT_EQ(out->GetNumberOfCells(), mesh->GetNumberOfCells());
    // And the input is left as it was.
    EXPECT_TRUE(SameBits(mesh->GetPoints()->GetData(), before->GetPoints()->GetData()));
    for (const char* name : { "Normals", "Tangents", "TCoords", "Temperature" })
    {
      EXPECT_TRUE(
        SameBits(mesh->GetPointData()->GetArray(name), before->GetPointData()->GetArray(name)))
        << name;
    }
  }
}

// dNdu/dNdv are derivatives in the parameters of dPdu/dPdv: Exact uses them with those only, and
// Approximate (which drops the d n_s, d n_t terms) never. Where they are not used the output is
// the one without them, bit for bit; where they are, it differs (the fits are not exact).
TEST(DisplacementMapFilter, NormalDerivativesOnlyWithSurfaceDerivativesInExact)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  auto withAll = MakeMesh(s, 24, 12, true, false, true);
  auto withoutN = MakeMesh(s, 24, 12, true, false, false);
  auto onlyN = vtkSmartPointer<vtkPolyData>::New();
  onlyN->DeepCopy(withAll);
  onlyN->GetPointData()->RemoveArray("dPdu");
  onlyN->GetPointData()->RemoveArray("dPdv");
  auto none = MakeMesh(s, 24, 12, false);
  for (int mode : AllModes)
  {
    SCOPED_TRACE(mode);
    auto all = Displace(withAll, image, mode);
    EXPECT_TRUE(AllFinite(all));
    EXPECT_EQ(
      SameOutput(all, Displace(withoutN, image, mode)), mode != vtkDisplacementMapFilter::Exact);
    EXPECT_TRUE(SameOutput(Displace(onlyN, image, mode), Displace(none, image, mode)));
  }
}

// Texture coordinates that are NaN or infinite locate no texel: in every mode and interpolation,
// with dPdu/dPdv and without, the output stays finite (points, normals, tangents), no error is
// raised, every other point moves exactly as in a run without them (a position depends on its
// own coordinates only), and the normals of points two or more grid steps away from them are
// those of the clean run (the bad coordinates reach no fit or polygon beyond their neighbours).
TEST(DisplacementMapFilter, NonFiniteTextureCoordinatesStayLocal)
{
  const Surface s = Torus();
  const int U = 24, V = 12;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // Interior points of the grid (i, j) (no seam partner), one coordinate or both bad.
  struct Spoilt
  {
    int I, J;
    double S, T;
  };
  const Spoilt spoilt[4] = { { 5, 3, nan, 0.25 }, { 11, 6, 0.5, inf }, { 17, 8, -inf, nan },
    { 3, 9, inf, -inf } };
  auto image = MakeHeightImage(s.Height, 64, 32);
  for (bool derivatives : { false, true })
  {
    auto clean = MakeMesh(s, U, V, derivatives);
    auto bad = vtkSmartPointer<vtkPolyData>::New();
    bad->DeepCopy(clean);
    for (const Spoilt& x : spoilt)
    {
      bad->GetPointData()->GetTCoords()->SetTuple2(
        static_cast<vtkIdType>(x.J) * (U + 1) + x.I, x.S, x.T);
    }
    for (int mode : AllModes)
    {
      for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear,
             vtkDisplacementMapFilter::Cubic })
      {
        SCOPED_TRACE("mode " + std::to_string(mode) + " interp " + std::to_string(interp) +
          (derivatives ? " with dPdu" : ""));
        vtkNew<vtkDisplacementMapFilter> f;
        auto obs = Watch(f);
        f->SetInputData(0, bad);
        f->SetInputData(1, image);
        f->SetNormalMode(mode);
        f->SetScaleFactor(0.1);
        f->SetMidlevel(0.5);
        f->SetInterpolation(interp);
        f->Update();
        EXPECT_EQ(obs->Errors, 0) << obs->Message;
        vtkPolyData* out = f->GetOutput();
        ASSERT_EQ(out->GetNumberOfPoints(), clean->GetNumberOfPoints());
        EXPECT_TRUE(AllFinite(out));
        auto ref = Displace(clean, image, mode, 0.1, 0.5, interp);
        vtkIdType moved = 0;
        double worst = 0.0;
        for (int j = 0; j <= V; ++j)
        {
          for (int i = 0; i <= U; ++i)
          {
            const vtkIdType id = static_cast<vtkIdType>(j) * (U + 1) + i;
            int distance = U;
            for (const Spoilt& x : spoilt)
            {
              distance = std::min(distance, std::max(std::abs(i - x.I), std::abs(j - x.J)));
            }
            double p[3], q[3], n[3], m[3];
            out->GetPoint(id, p);
            ref->GetPoint(id, q);
            moved += distance > 0 && (p[0] != q[0] || p[1] != q[1] || p[2] != q[2]);
            if (distance >= 2)
            {
              out->GetPointData()->GetNormals()->GetTuple(id, n);
              ref->GetPointData()->GetNormals()->GetTuple(id, m);
              worst = std::max(worst, AngleDeg({ n[0], n[1], n[2] }, { m[0], m[1], m[2] }));
            }
          }
        }
        EXPECT_EQ(moved, 0);
        EXPECT_LT(worst, 1e-9);
      }
    }
  }
}

// OutputPointsPrecision picks the type of the output points, normals and tangents as VTK's
// filters do; the values agree with the other precision's to float's precision.
TEST(DisplacementMapFilter, OutputPointsPrecision)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  for (const bool floatInput : { true, false })
  {
    auto mesh = MakeMesh(s, 32, 16, true, floatInput);
    vtkSmartPointer<vtkPolyData> outputs[3];
    for (int precision : { vtkAlgorithm::DEFAULT_PRECISION, vtkAlgorithm::SINGLE_PRECISION,
           vtkAlgorithm::DOUBLE_PRECISION })
    {
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetInputData(mesh);
      f->SetSourceData(image);
      f->SetScaleFactor(0.1);
      f->SetMidlevel(0.5);
      f->SetOutputPointsPrecision(precision);
      f->Update();
      vtkPolyData* out = f->GetOutput();
      const int expected = precision == vtkAlgorithm::SINGLE_PRECISION ||
          (precision == vtkAlgorithm::DEFAULT_PRECISION && floatInput)
        ? VTK_FLOAT
        : VTK_DOUBLE;
      EXPECT_EQ(out->GetPoints()->GetDataType(), expected) << precision << " " << floatInput;
      EXPECT_EQ(out->GetPointData()->GetNormals()->GetDataType(), expected);
      EXPECT_EQ(out->GetPointData()->GetTangents()->GetDataType(), expected);
      outputs[precision] = vtkSmartPointer<vtkPolyData>::New();
      outputs[precision]->DeepCopy(out);
    }
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      outputs[vtkAlgorithm::SINGLE_PRECISION]->GetPoint(i, a);
      outputs[vtkAlgorithm::DOUBLE_PRECISION]->GetPoint(i, b);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(a[c], b[c], 1e-6);
      }
    }
  }
}

// SetSourceConnection and SetSourceData are the height map's port, as VTK's two-input filters
// name their second input.
TEST(DisplacementMapFilter, SourceIsTheHeightMap)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  auto mesh = MakeMesh(s, 32, 16, true, true);
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(image);
  vtkNew<vtkDisplacementMapFilter> byPort, bySource;
  byPort->SetInputData(0, mesh);
  byPort->SetInputConnection(1, producer->GetOutputPort());
  bySource->SetInputData(0, mesh);
  bySource->SetSourceConnection(producer->GetOutputPort());
  byPort->Update();
  bySource->Update();
  EXPECT_EQ(bySource->GetInputConnection(1, 0), producer->GetOutputPort());
  EXPECT_TRUE(SameBits(
    byPort->GetOutput()->GetPoints()->GetData(), bySource->GetOutput()->GetPoints()->GetData()));
  EXPECT_GT(byPort->GetOutput()->GetNumberOfPoints(), 0);
}
