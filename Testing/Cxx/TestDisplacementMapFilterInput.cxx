// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter given unusual input: Scale 0, texture repeats, pieces, huge scales,
// 1x1 / 2x2 / 8192x8192 / constant / NaN height maps, bad input and point ids out of range.

#include "DisplacementFilterTestHelpers.h"

// Scale 0 changes nothing, to the bit (points in every mode; normals and tangents in the
// modes that derive them from the height map).
TEST(DisplacementMapFilter, ScaleZeroIsIdentity)
{
  const Surface s = Sphere();
  for (bool floatPoints : { false, true })
  {
    auto mesh = MakeMesh(s, 32, 16, true, floatPoints);
    auto image = MakeHeightImage(s.Height, 64, 32);
    for (int mode : AllModes)
    {
      auto out = Displace(mesh, image, mode, 0.0, 0.5, vtkDisplacementMapFilter::Cubic);
      EXPECT_TRUE(SameBits(mesh->GetPoints()->GetData(), out->GetPoints()->GetData())) << mode;
      if (mode != vtkDisplacementMapFilter::Mesh)
      {
        EXPECT_TRUE(SameBits(mesh->GetPointData()->GetNormals(), out->GetPointData()->GetNormals()))
          << mode;
        EXPECT_TRUE(
          SameBits(mesh->GetPointData()->GetTangents(), out->GetPointData()->GetTangents()))
          << mode;
      }
      EXPECT_TRUE(SameBits(mesh->GetPointData()->GetTCoords(), out->GetPointData()->GetTCoords()));
    }
  }
}

// dPdu/dPdv with respect to (u,v) while the texture coordinates are s = 0.25 + 3u,
// t = 2v (a parametric source's TextureRepeat/TextureOffset): the filter finds the scale,
// so the normals equal those from derivatives it fits itself (exact on a flat patch).
TEST(DisplacementMapFilter, DerivativesWithTextureRepeat)
{
  const Surface s = Rectangle();
  auto mesh = MakeMesh(s, 40, 30, true);
  vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
  for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
  {
    tc->SetTuple2(i, 0.25 + 3.0 * tc->GetComponent(i, 0), 2.0 * tc->GetComponent(i, 1));
  }
  auto fitted = vtkSmartPointer<vtkPolyData>::New();
  fitted->DeepCopy(mesh);
  fitted->GetPointData()->RemoveArray("dPdu");
  fitted->GetPointData()->RemoveArray("dPdv");
  auto image = MakeHeightImage(s.Height, 128, 128);
  for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
  {
    auto a = Displace(mesh, image, mode, 0.2, 0.5, vtkDisplacementMapFilter::Cubic);
    auto b = Displace(fitted, image, mode, 0.2, 0.5, vtkDisplacementMapFilter::Cubic);
    double worst = 0.0;
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      Vec na, nb;
      a->GetPointData()->GetNormals()->GetTuple(i, na.data());
      b->GetPointData()->GetNormals()->GetTuple(i, nb.data());
      worst = std::max(worst, AngleDeg(na, nb));
    }
    EXPECT_LT(worst, 1e-6) << mode;
  }
}

// Tangents come out orthogonal to the new normals, unit length, with the input's w.
TEST(DisplacementMapFilter, TangentsFollowNormals)
{
  const Surface s = Torus(0.15);
  auto mesh = MakeMesh(s, 48, 24, false);
  auto out =
    Displace(mesh, MakeHeightImage(s.Height, 128, 64), vtkDisplacementMapFilter::Exact, 0.15);
  auto t = TangentFrame(out);
  auto tin = TangentFrame(mesh);
  ASSERT_EQ(t->GetNumberOfComponents(), 4);
  double worst = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double n[3], tg[4], t0[4];
    out->GetPointData()->GetNormals()->GetTuple(i, n);
    t->GetTuple(i, tg);
    tin->GetTuple(i, t0);
    worst = std::max(worst, std::abs(n[0] * tg[0] + n[1] * tg[1] + n[2] * tg[2]));
    EXPECT_NEAR(tg[0] * tg[0] + tg[1] * tg[1] + tg[2] * tg[2], 1.0, 1e-12);
    EXPECT_EQ(tg[3], t0[3]);
  }
  EXPECT_LT(worst, 1e-12);
}

// Pieces pass through in count, and every piece gets the whole height map (the wavelet
// source would otherwise make only the piece's share of it).
TEST(DisplacementMapFilter, PiecesPassThrough)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(20);
  vtkNew<SphereTCoords> tcoords;
  tcoords->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkRTAnalyticSource> wavelet; // float scalars, streams by extent
  wavelet->SetWholeExtent(0, 63, 0, 31, 0, 0);
  vtkNew<vtkDisplacementMapFilter> f;
  f->SetInputConnection(0, tcoords->GetOutputPort());
  f->SetInputConnection(1, wavelet->GetOutputPort());
  f->SetScaleFactor(0.001);
  f->SetNormalModeToApproximate();
  tcoords->Update();
  const vtkIdType whole = tcoords->GetOutput()->GetNumberOfPoints();
  const int pieces = 3;
  vtkIdType total = 0;
  for (int p = 0; p < pieces; ++p)
  {
    f->UpdatePiece(p, pieces, 0);
    tcoords->UpdatePiece(p, pieces, 0);
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), tcoords->GetOutput()->GetNumberOfPoints());
    EXPECT_GT(f->GetOutput()->GetNumberOfPoints(), 0);
    int ext[6];
    wavelet->GetOutput()->GetExtent(ext);
    EXPECT_EQ(ext[1], 63);
    EXPECT_EQ(ext[3], 31);
    total += f->GetOutput()->GetNumberOfPoints();
  }
  EXPECT_GE(total, whole); // pieces share their boundary points
}

// Huge Scale: self-intersecting, but finite; float points clamp to the float range.
TEST(DisplacementMapFilter, HugeScaleStaysFinite)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 64, 32);
  for (bool floatPoints : { false, true })
  {
    auto mesh = MakeMesh(s, 32, 16, true, floatPoints);
    for (double scale : { 1e6, 1e30, 1e300, std::numeric_limits<double>::infinity() })
    {
      for (int mode : AllModes)
      {
        auto out = Displace(mesh, image, mode, scale, 0.5, vtkDisplacementMapFilter::Cubic);
        EXPECT_TRUE(AllFinite(out)) << scale << " mode " << mode;
      }
    }
  }
}

// 1x1 is a constant (with a warning); a constant map moves every point by the same distance along
// its normal and, in Approximate/Exact, keeps the normal; 2x2 works too.
TEST(DisplacementMapFilter, TinyAndConstantHeightMaps)
{
  const Surface s = Sphere();
  auto mesh = MakeMesh(s, 16, 8, false);
  for (int size : { 1, 2 })
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(size, size, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    std::memset(image->GetScalarPointer(), 255, static_cast<size_t>(size * size));
    {
      // Valid, but a single texel is seldom meant: one warning saying what it does.
      vtkNew<vtkDisplacementMapFilter> f;
      auto obs = Watch(f);
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      f->Update();
      EXPECT_EQ(obs->Errors, 0);
      EXPECT_EQ(obs->Warnings, size == 1 ? 1 : 0) << obs->Message;
      EXPECT_EQ(obs->Message.find("single texel") != std::string::npos, size == 1);
      EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints());
    }
    for (int mode : AllModes)
    {
      for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear,
             vtkDisplacementMapFilter::Cubic })
      {
        auto out = Displace(mesh, image, mode, 0.25, 0.5, interp);
        ASSERT_EQ(out->GetNumberOfPoints(), mesh->GetNumberOfPoints());
        for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
        {
          double p[3], n[3];
          out->GetPoint(i, p);
          out->GetPointData()->GetNormals()->GetTuple(i, n);
          // unit sphere: h = 1 (255 normalised), d = 0.25 (1 - 0.5)
          EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.125, 1e-12);
          if (mode != vtkDisplacementMapFilter::Mesh)
          {
            EXPECT_LT(AngleDeg({ n[0], n[1], n[2] }, { p[0], p[1], p[2] }), 1e-6);
          }
        }
      }
    }
  }
  // 2x2 with different texels: Linear at the texel centres gives the texels exactly.
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 1);
  image->AllocateScalars(VTK_UNSIGNED_SHORT, 1);
  auto* v = static_cast<unsigned short*>(image->GetScalarPointer());
  v[0] = 0;
  v[1] = 65535;
  v[2] = 13107; // 0.2
  v[3] = 32767;
  auto probes = Probes({ { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.25, 0.75 }, { 0.75, 0.75 } });
  auto out = Displace(probes, image, vtkDisplacementMapFilter::Approximate, 1.0, 0.0);
  const double expected[4] = { 0.0, 1.0, 0.2, 32767.0 / 65535.0 };
  for (int k = 0; k < 4; ++k)
  {
    double p[3];
    out->GetPoint(k, p);
    EXPECT_NEAR(p[2], expected[k], 1e-12);
  }
}

// Component selects the channel: an RGB map with different values per channel.
TEST(DisplacementMapFilter, ComponentSelectsTheChannel)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < 16; ++k)
  {
    v[3 * k] = 10;
    v[3 * k + 1] = 100;
    v[3 * k + 2] = 200;
  }
  auto probes = Probes({ { 0.3, 0.6 } });
  for (int component : { 0, 1, 2 })
  {
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputData(0, probes);
    f->SetInputData(1, image);
    f->SetHeightComponent(component);
    f->Update();
    double p[3];
    f->GetOutput()->GetPoint(0, p);
    EXPECT_NEAR(p[2], (component == 0 ? 10 : component == 1 ? 100 : 200) / 255.0, 1e-12);
  }
}

// 8192 x 8192 texels (64 MB of unsigned char): sampled where expected, in a few seconds.
TEST(DisplacementMapFilter, HugeHeightMap)
{
  const int N = 8192;
  vtkNew<vtkImageData> image;
  image->SetDimensions(N, N, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t j = 0; j < static_cast<size_t>(N); ++j)
  {
    std::memset(data + j * N, static_cast<int>((j * 256) / N), N);
  }
  std::vector<std::array<double, 2>> st;
  for (int k = 0; k < 256; ++k)
  {
    st.push_back({ 0.3, (k * 32 + 16.5) / N }); // row k*32+16, a texel centre
  }
  auto out = Displace(Probes(st), image, vtkDisplacementMapFilter::Exact, 1.0, 0.0);
  for (int k = 0; k < 256; ++k)
  {
    double p[3];
    out->GetPoint(k, p);
    EXPECT_NEAR(p[2], static_cast<double>(((k * 32 + 16) * 256) / N) / 255.0, 1e-12);
  }
}

// NaN and infinite heights count as Midlevel, with one warning naming the count.
TEST(DisplacementMapFilter, NaNHeightsAreMidlevelWithOneWarning)
{
  const int W = 8, H = 8;
  auto image = RandomImage(W, H, 9);
  auto* data = static_cast<float*>(image->GetScalarPointer());
  data[0] = std::numeric_limits<float>::quiet_NaN();
  data[9] = std::numeric_limits<float>::infinity();
  data[10] = -std::numeric_limits<float>::infinity();
  auto probes = Probes({ { 0.5 / W, 0.5 / H }, { 1.5 / W, 1.5 / H }, { 2.5 / W, 1.5 / H } });
  vtkNew<vtkDisplacementMapFilter> f;
  auto obs = Watch(f);
  f->SetInputData(0, probes);
  f->SetInputData(1, image);
  f->SetMidlevel(0.5);
  f->SetScaleFactor(1.0);
  f->SetInterpolationToNearest();
  f->Update();
  EXPECT_EQ(obs->Warnings, 1);
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_NE(obs->Message.find("3 height value(s)"), std::string::npos) << obs->Message;
  // Again: one more warning; and after an edit, the new count.
  f->Modified();
  f->Update();
  EXPECT_EQ(obs->Warnings, 2);
  data[20] = std::numeric_limits<float>::quiet_NaN();
  image->Modified();
  obs->Message.clear();
  f->Update();
  EXPECT_EQ(obs->Warnings, 3);
  EXPECT_NE(obs->Message.find("4 height value(s)"), std::string::npos) << obs->Message;
  for (vtkIdType i = 0; i < 3; ++i)
  {
    double p[3];
    f->GetOutput()->GetPoint(i, p);
    EXPECT_EQ(p[2], 0.0);
  }
  // Linear and Cubic next to the non-finite texels, in every normal mode: finite, and the very
  // output of the same map with Midlevel written in their place.
  vtkNew<vtkImageData> replaced;
  replaced->DeepCopy(image);
  auto* r = static_cast<float*>(replaced->GetScalarPointer());
  for (int k = 0; k < W * H; ++k)
  {
    r[k] = std::isfinite(r[k]) ? r[k] : 0.5f;
  }
  const Surface s = Rectangle();
  auto mesh = MakeMesh(s, 16, 16, false);
  for (int interp : { vtkDisplacementMapFilter::Linear, vtkDisplacementMapFilter::Cubic })
  {
    for (int mode : AllModes)
    {
      SCOPED_TRACE("interp " + std::to_string(interp) + " mode " + std::to_string(mode));
      auto out = Displace(mesh, image, mode, 0.1, 0.5, interp);
      auto ref = Displace(mesh, replaced, mode, 0.1, 0.5, interp);
      EXPECT_TRUE(AllFinite(out));
      EXPECT_TRUE(SameBits(out->GetPoints()->GetData(), ref->GetPoints()->GetData()));
      EXPECT_TRUE(SameBits(out->GetPointData()->GetNormals(), ref->GetPointData()->GetNormals()));
    }
  }
}

// Every bad input: an error naming the problem, empty output, no crash, input untouched.
TEST(DisplacementMapFilter, BadInputIsAnError)
{
  const Surface s = Rectangle();
  auto good = MakeMesh(s, 4, 4, false);
  auto image = RandomImage(4, 4, 1);
  struct Case
  {
    std::string Name, Expect;
    std::function<void(vtkDisplacementMapFilter*)> Setup;
  };
  auto noTCoords = vtkSmartPointer<vtkPolyData>::New();
  noTCoords->DeepCopy(good);
  noTCoords->GetPointData()->SetTCoords(nullptr);
  auto noNormals = vtkSmartPointer<vtkPolyData>::New();
  noNormals->DeepCopy(good);
  noNormals->GetPointData()->SetNormals(nullptr);
  // Arrays shorter than the points (read out of bounds before they were checked).
  auto shortNormals = vtkSmartPointer<vtkPolyData>::New();
  shortNormals->DeepCopy(good);
  shortNormals->GetPointData()->GetNormals()->SetNumberOfTuples(3);
  auto shortTCoords = vtkSmartPointer<vtkPolyData>::New();
  shortTCoords->DeepCopy(good);
  shortTCoords->GetPointData()->GetTCoords()->SetNumberOfTuples(3);
  vtkNew<vtkImageData> empty;
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 4, 2);
  volume->AllocateScalars(VTK_FLOAT, 1);
  vtkNew<vtkImageData> ints;
  ints->SetDimensions(4, 4, 1);
  ints->AllocateScalars(VTK_INT, 1);
  const unsigned long before = good->GetMTime();
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> inputTimes;
  for (vtkDataObject* x : std::initializer_list<vtkDataObject*>{
         noTCoords, noNormals, shortNormals, shortTCoords, empty, volume, ints, image })
  {
    inputTimes.emplace_back(x, x->GetMTime());
  }
  auto Inputs = [](vtkDataObject* surface, vtkDataObject* map)
  {
    return [=](vtkDisplacementMapFilter* f)
    {
      f->SetInputData(0, surface);
      f->SetInputData(1, map);
    };
  };
  std::vector<Case> cases = {
    { "no tcoords", "texture coordinates", Inputs(noTCoords, image) },
    { "no normals", "normals", Inputs(noNormals, image) },
    { "short normals", "Normals has 3 tuples for 25 points", Inputs(shortNormals, image) },
    { "short tcoords", "TCoords has 3 tuples for 25 points", Inputs(shortTCoords, image) },
    { "empty image", "empty", Inputs(good, empty) },
    { "volume", "2-D image", Inputs(good, volume) },
    { "int scalars", "unsigned char", Inputs(good, ints) },
    { "component", "HeightComponent 3",
      [&](vtkDisplacementMapFilter* f)
      {
        f->SetInputData(0, good);
        f->SetInputData(1, image);
        f->SetHeightComponent(3);
      } },
    { "no height map", "port 1", [&](vtkDisplacementMapFilter* f) { f->SetInputData(0, good); } },
    { "polydata on port 1", "vtkImageData", Inputs(good, good) },
    { "image on port 0", "vtkPolyData", Inputs(image, image) },
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Name);
    vtkNew<vtkDisplacementMapFilter> f;
    auto obs = Watch(f);
    c.Setup(f);
    f->Update();
    EXPECT_GE(obs->Errors, 1);
    EXPECT_NE(obs->Message.find(c.Expect), std::string::npos) << obs->Message;
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(f->GetOutput()->GetPointData()->GetNumberOfArrays(), 0);
  }
  EXPECT_EQ(good->GetMTime(), before);
  EXPECT_EQ(good->GetNumberOfPoints(), 25);
  // The other inputs are untouched too.
  for (const auto& x : inputTimes)
  {
    EXPECT_EQ(x.first->GetMTime(), x.second) << x.first->GetClassName();
  }
  // An empty surface is not an error: empty in, empty out.
  vtkNew<vtkPolyData> nothing;
  vtkNew<vtkDisplacementMapFilter> f;
  auto obs = Watch(f);
  f->SetInputData(0, nothing);
  f->SetInputData(1, image);
  f->Update();
  EXPECT_EQ(obs->Errors, 0);
  EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
}

// A polygon naming a point the input does not have (past the end, or negative) made the
// passes read and BuildLinks write outside the point arrays. In every mode, also after a
// good execution.
TEST(DisplacementMapFilter, PointIdsOutOfRangeAreAnError)
{
  const Surface s = Rectangle();
  auto image = RandomImage(4, 4, 1);
  for (const int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact,
         vtkDisplacementMapFilter::Mesh, vtkDisplacementMapFilter::Input })
  {
    for (const vtkIdType bad : { vtkIdType(25), vtkIdType(-1), vtkIdType(1) << 40 })
    {
      SCOPED_TRACE(std::to_string(mode) + " " + std::to_string(bad));
      auto mesh = MakeMesh(s, 4, 4, true);
      mesh->GetPolys()->ConvertTo64BitStorage();
      vtkDataArray* conn = mesh->GetPolys()->GetConnectivityArray();
      const vtkIdType last = conn->GetNumberOfTuples() - 1;
      const double good = conn->GetComponent(last, 0);
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetNormalMode(mode);
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      auto obs = Watch(f);
      f->Update();
      ASSERT_EQ(obs->Errors, 0);
      ASSERT_EQ(f->GetOutput()->GetNumberOfPoints(), 25);

      conn->SetComponent(last, 0, static_cast<double>(bad));
      mesh->GetPolys()->Modified();
      f->Update();
      const int errors = obs->Errors;
      EXPECT_GE(errors, 1);
      EXPECT_NE(obs->Message.find("point id outside [0, 25)"), std::string::npos) << obs->Message;
      EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
      EXPECT_EQ(mesh->GetNumberOfPoints(), 25);

      conn->SetComponent(last, 0, good);
      mesh->GetPolys()->Modified();
      f->Update();
      EXPECT_EQ(obs->Errors, errors);
      EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 25);
    }
  }
}

// Where pass 1 reads no cells (None, and Approximate with dPdu/dPdv) the id check runs beside it:
// no pass may read through a bad id first (the seam sweep writes through them, the derivative-scale
// estimate reads each polygon's first two). A bad id in the first, a middle or the last polygon, or
// in a triangle strip, 32- or 64-bit connectivity, at 1 and 2 threads, seams merged or not: the
// error, an empty output and the input untouched.
TEST(DisplacementMapFilter, PointIdsOutOfRangeBesidePass1)
{
  const Surface s = Rectangle();
  auto image = RandomImage(4, 4, 1);
  for (const int threads : { 1, 2 })
  {
    vtkSMPTools::Initialize(threads);
    for (const bool ids64 : { false, true })
    {
      for (const bool strip : { false, true })
      {
        for (const vtkIdType where : { vtkIdType(0), vtkIdType(8), vtkIdType(-1) })
        {
          for (const vtkIdType bad : { vtkIdType(25), vtkIdType(-7),
                 ids64 ? vtkIdType(1) << 40 : vtkIdType(VTK_TYPE_INT32_MAX) })
          {
            for (const int mode :
              { vtkDisplacementMapFilter::Input, vtkDisplacementMapFilter::Approximate })
            {
              for (const bool merge : { true, false })
              {
                SCOPED_TRACE(std::to_string(threads) + " threads, " + (ids64 ? "64" : "32") +
                  "-bit, " + (strip ? "strip" : "polygon") + " at " + std::to_string(where) +
                  ", id " + std::to_string(bad) + ", mode " + std::to_string(mode) +
                  (merge ? ", merged" : ", apart"));
                auto mesh = MakeMesh(s, 4, 4, true);
                vtkCellArray* cells = mesh->GetPolys();
                if (strip)
                {
                  vtkNew<vtkCellArray> strips;
                  const vtkIdType ids[4] = { 0, 5, 1, 6 };
                  strips->InsertNextCell(4, ids);
                  mesh->SetStrips(strips);
                  cells = strips;
                }
                if (ids64)
                {
                  cells->ConvertTo64BitStorage();
                }
                else
                {
                  cells->ConvertTo32BitStorage();
                }
                vtkDataArray* conn = cells->GetConnectivityArray();
                const vtkIdType at = where < 0 ? conn->GetNumberOfTuples() - 1
                                               : std::min(where, conn->GetNumberOfTuples() - 1);
                const double good = conn->GetComponent(at, 0);
                vtkNew<vtkDisplacementMapFilter> f;
                f->SetNormalMode(mode);
                f->SetMergeSeams(merge);
                f->SetInputData(0, mesh);
                f->SetInputData(1, image);
                auto obs = Watch(f);
                f->Update();
                ASSERT_EQ(obs->Errors, 0) << obs->Message;
                ASSERT_EQ(f->GetOutput()->GetNumberOfPoints(), 25);

                conn->SetComponent(at, 0, static_cast<double>(bad));
                cells->Modified();
                auto pointsBefore =
                  vtkSmartPointer<vtkDataArray>::Take(mesh->GetPoints()->GetData()->NewInstance());
                pointsBefore->DeepCopy(mesh->GetPoints()->GetData());
                auto connBefore = vtkSmartPointer<vtkDataArray>::Take(conn->NewInstance());
                connBefore->DeepCopy(conn);
                f->SetScaleFactor(0.5); // a new execution either way
                f->Update();
                const int errors = obs->Errors;
                EXPECT_GE(errors, 1);
                EXPECT_NE(obs->Message.find("point id outside [0, 25)"), std::string::npos)
                  << obs->Message;
                EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
                EXPECT_EQ(f->GetOutput()->GetNumberOfCells(), 0);
                EXPECT_TRUE(SameBits(mesh->GetPoints()->GetData(), pointsBefore));
                EXPECT_TRUE(SameBits(conn, connBefore));

                conn->SetComponent(at, 0, good);
                cells->Modified();
                f->Update();
                EXPECT_EQ(obs->Errors, errors);
                EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 25);
              }
            }
          }
        }
      }
    }
  }
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

// The heights can be any point array of the height map, chosen by name with
// SetInputArrayToProcess as in VTK's filters: with the heights in "Height" and a colour
// array as the active scalars, the output is the one the heights give as scalars.
TEST(DisplacementMapFilter, HeightArrayChosenWithSetInputArrayToProcess)
{
  const Surface s = Torus();
  auto mesh = MakeMesh(s, 16, 8, true);
  auto asScalars = MakeHeightImage(s.Height, 32, 16);
  vtkDataArray* scalars = asScalars->GetPointData()->GetScalars();
  auto heights = vtk::TakeSmartPointer(scalars->NewInstance());
  heights->DeepCopy(scalars);
  heights->SetName("Height");
  vtkNew<vtkUnsignedCharArray> colours; // the active scalars, which must not be read
  colours->SetName("Colour");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(heights->GetNumberOfTuples());
  colours->Fill(200);
  auto named = vtkSmartPointer<vtkImageData>::New();
  named->SetDimensions(asScalars->GetDimensions());
  named->GetPointData()->SetScalars(colours);
  named->GetPointData()->AddArray(heights);

  auto want = Displace(mesh, asScalars, vtkDisplacementMapFilter::Exact);
  vtkNew<vtkDisplacementMapFilter> f;
  f->SetInputData(0, mesh);
  f->SetSourceData(named);
  f->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Height");
  f->SetScaleFactor(0.1);
  f->SetMidlevel(0.5);
  f->SetWrapToRepeat();
  f->Update();
  EXPECT_TRUE(SameBits(f->GetOutput()->GetPoints()->GetData(), want->GetPoints()->GetData()));
  EXPECT_TRUE(
    SameBits(f->GetOutput()->GetPointData()->GetNormals(), want->GetPointData()->GetNormals()));

  // A name the map does not have is an error with an empty output.
  auto messages = Watch(f);
  f->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Elevation");
  f->Update();
  EXPECT_GE(messages->Errors, 1);
  EXPECT_NE(messages->Message.find("SetInputArrayToProcess"), std::string::npos)
    << messages->Message;
  EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
}

// Other arrays pass through; None keeps normals; PrintSelf names every setting.
TEST(DisplacementMapFilter, ArraysSettingsAndPrint)
{
  const Surface s = Torus();
  auto mesh = MakeMesh(s, 8, 4, true);
  vtkNew<vtkIntArray> ids;
  ids->SetName("Ids");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    ids->InsertNextValue(static_cast<int>(i));
  }
  mesh->GetPointData()->AddArray(ids);
  auto out = Displace(mesh, MakeHeightImage(s.Height, 32, 16), vtkDisplacementMapFilter::Input);
  EXPECT_TRUE(SameBits(out->GetPointData()->GetArray("Ids"), ids));
  EXPECT_TRUE(SameBits(out->GetPointData()->GetNormals(), mesh->GetPointData()->GetNormals()));
  EXPECT_EQ(out->GetNumberOfCells(), mesh->GetNumberOfCells());

  vtkNew<vtkDisplacementMapFilter> f;
  EXPECT_EQ(f->GetNormalMode(), vtkDisplacementMapFilter::Exact);
  f->SetNormalModeToMesh();
  EXPECT_EQ(f->GetNormalMode(), vtkDisplacementMapFilter::Mesh);
  f->SetNormalModeToApproximate();
  f->SetWrapToMirroredRepeat();
  EXPECT_EQ(f->GetWrap(), vtkDisplacementMapFilter::MirroredRepeat);
  f->SetInterpolationToCubic();
  f->SetMidlevel(0.25);
  std::ostringstream os;
  f->Print(os);
  for (const char* key :
    { "ScaleFactor: 1", "Midlevel: 0.25", "HeightComponent: 0", "Wrap: MirroredRepeat",
      "Interpolation: Cubic", "NormalMode: Approximate", "MergeSeams: On", "SeamTolerance: 1e-06" })
  {
    EXPECT_NE(os.str().find(key), std::string::npos) << key;
  }
}
