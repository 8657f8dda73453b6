// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkDisplacementMapFilter: sampling against an independent OpenGL-spec reference, seams,
// poles, threads, pieces and re-execution.

#include "DisplacementFilterTestHelpers.h"

// The wrap modes are vtkTexture's, value for value, so that a texture's GetWrap() can be passed
// to SetWrap().
static_assert(static_cast<int>(vtkDisplacementMapFilter::ClampToEdge) ==
      static_cast<int>(vtkTexture::ClampToEdge) &&
    static_cast<int>(vtkDisplacementMapFilter::Repeat) == static_cast<int>(vtkTexture::Repeat) &&
    static_cast<int>(vtkDisplacementMapFilter::MirroredRepeat) ==
      static_cast<int>(vtkTexture::MirroredRepeat) &&
    static_cast<int>(vtkDisplacementMapFilter::ClampToBorder) ==
      static_cast<int>(vtkTexture::ClampToBorder),
  "vtkDisplacementMapFilter's Wrap values must be vtkTexture's");

// The Linear and Nearest samples equal an independent transcription of OpenGL's sampling
// rules for every wrap mode, inside and outside [0,1] (so the CPU displacement matches
// what a vtkTexture shows).
TEST(DisplacementMapFilter, SamplingMatchesOpenGLRules)
{
  const int W = 7, H = 5;
  auto image = RandomImage(W, H, 3);
  const float* img = static_cast<float*>(image->GetScalarPointer());
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  std::vector<std::array<double, 2>> st = RandomCoordinates(random, 400);
  st.push_back({ 0.0, 0.0 });
  st.push_back({ 1.0, 1.0 });
  st.push_back({ 0.5 / W, 0.5 / H });
  auto probes = Probes(st);
  for (int wrap : { vtkDisplacementMapFilter::ClampToEdge, vtkDisplacementMapFilter::Repeat,
         vtkDisplacementMapFilter::MirroredRepeat, vtkDisplacementMapFilter::ClampToBorder })
  {
    for (int interp : { vtkDisplacementMapFilter::Nearest, vtkDisplacementMapFilter::Linear })
    {
      auto out = Displace(probes, image, vtkDisplacementMapFilter::Input, 1.0, 0.0, interp, wrap);
      for (size_t k = 0; k < st.size(); ++k)
      {
        const double expected = interp == vtkDisplacementMapFilter::Linear
          ? GLLinear(img, W, H, wrap, st[k][0], st[k][1])
          : GLNearest(img, W, H, wrap, st[k][0], st[k][1]);
        double p[3];
        out->GetPoint(static_cast<vtkIdType>(k), p);
        ASSERT_NEAR(p[2], expected, 1e-12) << "wrap " << wrap << " interp " << interp << " at ("
                                           << st[k][0] << ", " << st[k][1] << ")";
      }
    }
  }
}

// Cubic is Catmull-Rom: it reproduces a quadratic exactly (away from clamped edges), so
// height and slope, hence the normal of z = Scale h, are exact; Linear is exact for a
// bilinear ramp.
TEST(DisplacementMapFilter, CubicAndLinearReproducePolynomials)
{
  const int W = 16, H = 12;
  auto quad = [](double s, double t)
  { return 0.2 + 0.3 * s - 0.1 * t + 0.4 * s * s + 0.25 * s * t - 0.3 * t * t; };
  auto grad = [](double s, double t) {
    return std::array<double, 2>{ 0.3 + 0.8 * s + 0.25 * t, -0.1 + 0.25 * s - 0.6 * t };
  };
  vtkNew<vtkImageData> image;
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(VTK_DOUBLE, 1);
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      image->SetScalarComponentFromDouble(i, j, 0, 0, quad((i + 0.5) / W, (j + 0.5) / H));
    }
  }
  std::vector<std::array<double, 2>> st;
  for (int k = 0; k < 50; ++k)
  {
    st.push_back(
      { 0.2 + 0.6 * std::fmod(k * 0.618034, 1.0), 0.2 + 0.6 * std::fmod(k * 0.41421, 1.0) });
  }
  auto probes = Probes(st);
  const double scale = 0.7;
  for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
  {
    auto out = Displace(probes, image, mode, scale, 0.0, vtkDisplacementMapFilter::Cubic,
      vtkDisplacementMapFilter::ClampToEdge);
    for (size_t k = 0; k < st.size(); ++k)
    {
      double p[3], n[3];
      out->GetPoint(static_cast<vtkIdType>(k), p);
      out->GetPointData()->GetNormals()->GetTuple(static_cast<vtkIdType>(k), n);
      EXPECT_NEAR(p[2], scale * quad(st[k][0], st[k][1]), 1e-12);
      const auto g = grad(st[k][0], st[k][1]);
      const Vec truth = Unit({ -scale * g[0], -scale * g[1], 1.0 });
      EXPECT_LT(AngleDeg({ n[0], n[1], n[2] }, truth), 1e-9);
    }
  }
}

// Texture seams and poles: coincident points move identically and (same input normal)
// get identical normals, in every mode, even where the height map itself disagrees across
// the seam (ClampToEdge, random texels). Without MergeSeams they would not.
TEST(DisplacementMapFilter, SeamsAndPolesAreWatertight)
{
  const Surface s = Sphere(0.2);
  auto mesh = MakeMesh(s, 24, 16, false);
  auto image = RandomImage(32, 16, 5);
  const int U = 24, V = 16;
  // Coincident points move by one displacement: outputs as far apart as the inputs were
  // (the closed form puts seam and pole duplicates up to 1e-16 apart), exactly equal when
  // the inputs were; and exactly one normal (None keeps the input normals).
  auto check = [&](vtkPolyData* out, bool normalsToo, bool expectIdentical)
  {
    int differing = 0;
    for (int j = 0; j <= V; ++j)
    {
      const vtkIdType a = static_cast<vtkIdType>(j) * (U + 1), b = a + U; // u = 0 and u = 1
      std::vector<vtkIdType> group = { b };
      if (j == 0 || j == V)
      {
        for (int i = 1; i < U; ++i)
        {
          group.push_back(a + i); // the whole pole row
        }
      }
      double pa[3], na[3], ia[3];
      out->GetPoint(a, pa);
      mesh->GetPoint(a, ia);
      out->GetPointData()->GetNormals()->GetTuple(a, na);
      for (vtkIdType g : group)
      {
        double pb[3], nb[3], ib[3];
        out->GetPoint(g, pb);
        mesh->GetPoint(g, ib);
        out->GetPointData()->GetNormals()->GetTuple(g, nb);
        const double din = std::sqrt(vtkMath::Distance2BetweenPoints(ia, ib));
        const double dout = std::sqrt(vtkMath::Distance2BetweenPoints(pa, pb));
        // Exactly equal values (+0 and -0 are the same place).
        const bool samePoint = din == 0.0 ? dout == 0.0 : dout <= din + 1e-15;
        const bool sameNormal = !normalsToo || (na[0] == nb[0] && na[1] == nb[1] && na[2] == nb[2]);
        differing += samePoint && sameNormal ? 0 : 1;
        if (expectIdentical)
        {
          EXPECT_TRUE(samePoint) << "row " << j << " point " << g << ": " << dout << " vs " << din;
          EXPECT_TRUE(sameNormal) << "row " << j << " point " << g;
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_TRUE(std::isfinite(na[k]));
      }
    }
    return differing;
  };
  // Float arrays too, whose outputs are rounded to float.
  for (bool floatPoints : { false, true })
  {
    mesh = MakeMesh(s, 24, 16, false, floatPoints);
    for (int wrap : { vtkDisplacementMapFilter::Repeat, vtkDisplacementMapFilter::ClampToEdge })
    {
      for (int mode : AllModes)
      {
        SCOPED_TRACE(std::string("mode ") + std::to_string(mode) + " wrap " + std::to_string(wrap) +
          (floatPoints ? " float" : " double"));
        auto out = Displace(mesh, image, mode, 0.2, 0.5, vtkDisplacementMapFilter::Cubic, wrap);
        check(out, mode != vtkDisplacementMapFilter::Input, true);
        EXPECT_TRUE(AllFinite(out));
      }
    }
  }
  // The same with MergeSeams off shows cracks: the test can fail.
  vtkNew<vtkDisplacementMapFilter> f;
  f->SetInputData(0, mesh);
  f->SetInputData(1, image);
  f->SetWrapToClampToEdge();
  f->SetScaleFactor(0.2);
  f->MergeSeamsOff();
  f->Update();
  EXPECT_GT(check(f->GetOutput(), true, false), 0);
  // Pole normals are finite and point along the axis (the height is radial there).
  auto out = Displace(MakeMesh(s, 24, 16, false), MakeHeightImage(s.Height, 256, 128),
    vtkDisplacementMapFilter::Exact, 0.2, 0.5, vtkDisplacementMapFilter::Cubic);
  double n[3];
  out->GetPointData()->GetNormals()->GetTuple(0, n);
  EXPECT_LT(AngleDeg({ n[0], n[1], n[2] }, { 0, -1, 0 }), 1.0);
}

// A seam point where two boundary fans meet (a bowtie: two triangles touching only at it) must be
// found by the seam sweep whatever its neighbours' ids. The sweep sums, per point, a hash of each
// corner's next point minus one of its previous point; here those sums are h(117) - h(422) +
// h(1199) - h(894), and 117 + 1199 = 422 + 894, so a hash that is nearly additive (one multiply
// and an xor-shift: it cancels for these ids) misses the point: it then moves by its own height,
// not its duplicate's, and the surface cracks.
TEST(DisplacementMapFilter, BowtieSeamPointMerges)
{
  const vtkIdType p = 1200, q = 1201;
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  points->SetNumberOfPoints(q + 1);
  vtkNew<vtkDoubleArray> normals, tcoords;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(q + 1);
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(q + 1);
  for (vtkIdType i = 0; i <= q; ++i)
  {
    // Points no polygon uses, apart from one another and from the triangles.
    points->SetPoint(i, 3.0 + static_cast<double>(i), 5.0, 0.0);
    normals->SetTuple3(i, 0.0, 0.0, 1.0);
    tcoords->SetTuple2(i, 0.5, 0.5);
  }
  // p and q at one place on either side of a texture seam (s = 0.25 and 0.75).
  points->SetPoint(p, 0.0, 0.0, 0.0);
  points->SetPoint(q, 0.0, 0.0, 0.0);
  tcoords->SetTuple2(p, 0.25, 0.5);
  tcoords->SetTuple2(q, 0.75, 0.5);
  points->SetPoint(117, 1.0, 0.0, 0.0);
  points->SetPoint(422, 0.0, 1.0, 0.0);
  points->SetPoint(1199, -1.0, 0.0, 0.0);
  points->SetPoint(894, 0.0, -1.0, 0.0);
  points->SetPoint(0, 1.0, -1.0, 0.0);
  points->SetPoint(1, 1.0, -0.5, 0.0);
  vtkNew<vtkCellArray> tris;
  for (const std::array<vtkIdType, 3>& t : { std::array<vtkIdType, 3>{ p, 117, 422 },
         std::array<vtkIdType, 3>{ p, 1199, 894 }, std::array<vtkIdType, 3>{ q, 0, 1 } })
  {
    tris->InsertNextCell(3, t.data());
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(tris);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetTCoords(tcoords);
  // Heights growing with s: p's and q's own differ.
  auto image = MakeHeightImage([](double s, double) { return s; }, 8, 4);
  for (int mode : AllModes)
  {
    for (bool merge : { true, false })
    {
      SCOPED_TRACE(std::string("mode ") + std::to_string(mode) + (merge ? " merged" : " apart"));
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      f->SetNormalMode(mode);
      f->SetMergeSeams(merge);
      auto obs = Watch(f);
      f->Update();
      ASSERT_EQ(obs->Errors, 0) << obs->Message;
      double xp[3], xq[3];
      f->GetOutput()->GetPoint(p, xp);
      f->GetOutput()->GetPoint(q, xq);
      // Merged, both move by the mean of their heights (0.25 and 0.75: the image is linear in s).
      if (merge)
      {
        EXPECT_EQ(xp[2], xq[2]);
        EXPECT_NEAR(xp[2], 0.5, 1e-12);
      }
      else
      {
        EXPECT_NEAR(xq[2] - xp[2], 0.5, 1e-12);
      }
    }
  }
}

// Results do not depend on the number of threads, bit for bit.
TEST(DisplacementMapFilter, SameResultAtAnyThreadCount)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  // Double arrays and float ones: a mesh big enough to be split between threads, with points
  // that need a fallback (a zero and a NaN normal, a tangent along the normal) near the start
  // and the middle.
  for (bool floatPoints : { false, true })
  {
    auto mesh = MakeMesh(s, 256, 128, false, floatPoints);
    vtkDataArray* normals = mesh->GetPointData()->GetNormals();
    auto tangents = TangentFrame(mesh);
    const vtkIdType middle = mesh->GetNumberOfPoints() / 2;
    normals->SetTuple3(5, 0.0, 0.0, 0.0);
    normals->SetTuple3(middle, std::nan(""), 0.0, 1.0);
    double n[3];
    normals->GetTuple(middle + 1, n);
    tangents->SetTuple4(middle + 1, n[0], n[1], n[2], 1.0);
    for (int mode : AllModes)
    {
      vtkSMPTools::Initialize(1);
      auto one = Displace(mesh, image, mode, 0.1, 0.5, vtkDisplacementMapFilter::Cubic);
      vtkSMPTools::Initialize(2);
      ASSERT_EQ(vtkSMPTools::GetEstimatedNumberOfThreads(), 2);
      auto two = Displace(mesh, image, mode, 0.1, 0.5, vtkDisplacementMapFilter::Cubic);
      EXPECT_TRUE(SameBits(one->GetPoints()->GetData(), two->GetPoints()->GetData()))
        << mode << " " << floatPoints;
      EXPECT_TRUE(SameBits(one->GetPointData()->GetNormals(), two->GetPointData()->GetNormals()))
        << mode << " " << floatPoints;
      EXPECT_TRUE(SameBits(one->GetPointData()->GetTangents(), two->GetPointData()->GetTangents()))
        << mode << " " << floatPoints;
      // (None passes the NaN normal through.)
      EXPECT_TRUE(mode == vtkDisplacementMapFilter::Input || AllFinite(one))
        << mode << " " << floatPoints;
    }
  }
  // Back to every core (VTK 9.1 keeps 1 thread on Initialize(0) after Initialize(1)).
  vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
}

// Re-execution: whatever changes after a first execution (Scale, points, texture coordinates,
// normals, connectivity, in place or by new objects), the output must be, to the bit, that of a
// fresh filter; and each change must matter (the output moves), so that stale data would show.
TEST(DisplacementMapFilter, ReExecutionMatchesFreshFilter)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  const int U = 48, V = 24;
  auto same = [](vtkPolyData* a, vtkPolyData* b)
  {
    return SameBits(a->GetPoints()->GetData(), b->GetPoints()->GetData()) &&
      SameBits(a->GetPointData()->GetNormals(), b->GetPointData()->GetNormals()) &&
      SameBits(a->GetPointData()->GetTangents(), b->GetPointData()->GetTangents());
  };
  for (int mode : AllModes)
  {
    for (bool releaseData : { false, true })
    {
      auto mesh = MakeMesh(s, U, V, false, true);
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      f->SetNormalMode(mode);
      f->SetMidlevel(0.5);
      f->SetReleaseDataFlag(releaseData);
      auto check = [&](double scale, const char* what)
      {
        auto before = vtkSmartPointer<vtkPolyData>::New();
        if (f->GetOutput()->GetPoints())
        {
          before->DeepCopy(f->GetOutput());
        }
        f->SetScaleFactor(scale);
        f->Update();
        auto fresh = Displace(mesh, image, mode, scale, 0.5);
        EXPECT_TRUE(same(f->GetOutput(), fresh)) << what << ", mode " << mode;
        if (before->GetPoints())
        {
          EXPECT_FALSE(same(before, fresh)) << what << " changed nothing, mode " << mode;
        }
      };
      check(0.1, "first execution");
      check(0.2, "Scale");

      // Points moved in place: one seam duplicate pulled off its twin (the groups change).
      vtkDataArray* pts = mesh->GetPoints()->GetData();
      pts->SetComponent(5 * (U + 1) + U, 2, pts->GetComponent(5 * (U + 1) + U, 2) + 0.05);
      pts->Modified();
      check(0.2, "points in place");

      // (Stretched, not only shifted: Exact's fits are derivatives in texture space.)
      vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
      for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
      {
        tc->SetComponent(i, 0, 1.01 * tc->GetComponent(i, 0) + 0.01);
      }
      tc->Modified();
      check(0.2, "texture coordinates in place");

      vtkDataArray* nrm = mesh->GetPointData()->GetNormals();
      for (vtkIdType i = 0; i < nrm->GetNumberOfTuples(); i += 7)
      {
        nrm->SetComponent(i, 1, nrm->GetComponent(i, 1) + 0.01);
      }
      nrm->Modified();
      check(0.2, "normals in place");

      // Normals reversed in place: every polygon's orientation (Mesh) flips with them.
      for (vtkIdType i = 0; i < nrm->GetNumberOfTuples(); ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          nrm->SetComponent(i, k, -nrm->GetComponent(i, k));
        }
      }
      nrm->Modified();
      check(0.2, "normals reversed in place");

      // Connectivity changed in place: the seam closed (polygons use the first column
      // instead of its duplicates), so the links and the boundary change.
      vtkDataArray* conn = mesh->GetPolys()->GetConnectivityArray();
      for (vtkIdType k = 0; k < conn->GetNumberOfValues(); ++k)
      {
        const vtkIdType id = static_cast<vtkIdType>(conn->GetComponent(k, 0));
        if (id % (U + 1) == U)
        {
          conn->SetComponent(k, 0, static_cast<double>(id - U));
        }
      }
      // (vtkCellArray's MTime does not include its arrays': the pipeline needs both.)
      conn->Modified();
      mesh->GetPolys()->Modified();
      check(0.2, "connectivity in place");

      // New objects in the same input: points and polygons of another mesh.
      auto other = MakeMesh(s, U, V, false, true);
      vtkNew<vtkPoints> newPoints;
      newPoints->DeepCopy(other->GetPoints());
      mesh->SetPoints(newPoints);
      vtkNew<vtkCellArray> newPolys;
      newPolys->DeepCopy(other->GetPolys());
      mesh->SetPolys(newPolys);
      check(0.3, "new points and polygons");
    }
  }
}

// Runs @a change on the input of a filter that has executed, re-executes, and expects the output
// of a fresh filter (and a different one than before, so that stale data would show).
template <typename Change>
void ExpectFreshAfter(vtkDisplacementMapFilter* f, const char* what, Change&& change)
{
  auto before = vtkSmartPointer<vtkPolyData>::New();
  f->Update();
  before->DeepCopy(f->GetOutput());
  change();
  f->Update();
  vtkNew<vtkDisplacementMapFilter> fresh;
  fresh->SetInputData(0, f->GetInputDataObject(0, 0));
  fresh->SetInputData(1, f->GetInputDataObject(1, 0));
  fresh->SetNormalMode(f->GetNormalMode());
  fresh->SetScaleFactor(f->GetScaleFactor());
  fresh->SetMidlevel(f->GetMidlevel());
  fresh->SetHeightComponent(f->GetHeightComponent());
  fresh->SetWrap(f->GetWrap());
  fresh->SetInterpolation(f->GetInterpolation());
  fresh->SetMergeSeams(f->GetMergeSeams());
  fresh->SetSeamTolerance(f->GetSeamTolerance());
  fresh->Update();
  const int mode = f->GetNormalMode();
  EXPECT_TRUE(SameOutput(f->GetOutput(), fresh->GetOutput())) << what << ", mode " << mode;
  EXPECT_FALSE(SameOutput(before, fresh->GetOutput())) << what << " changed nothing, mode " << mode;
}

// VTK's contract for data changed in place is that some object the pipeline sees is Modified():
// the polydata or its point data will do (vtkPoints::SetPoint and vtkDataArray::SetComponent
// leave the MTimes alone). The output must follow such a change as the pipeline does.
TEST(DisplacementMapFilter, ReExecutionAfterContainerModified)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  const int U = 48, V = 24;
  for (int mode : AllModes)
  {
    auto mesh = MakeMesh(s, U, V, false, true);
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, image);
    f->SetNormalMode(mode);
    f->SetMidlevel(0.5);
    f->SetScaleFactor(0.2);
    ExpectFreshAfter(f, "points in place, then the polydata Modified()",
      [&]()
      {
        // One seam duplicate pulled off its twin, and the points near it moved.
        vtkPoints* pts = mesh->GetPoints();
        for (vtkIdType i = 4 * (U + 1) + 1; i < 6 * (U + 1); ++i)
        {
          double p[3];
          pts->GetPoint(i, p);
          p[2] += 0.05;
          pts->SetPoint(i, p);
        }
        mesh->Modified();
      });
    ExpectFreshAfter(f, "normals in place, then the point data Modified()",
      [&]()
      {
        vtkDataArray* nrm = mesh->GetPointData()->GetNormals();
        for (vtkIdType i = 0; i < nrm->GetNumberOfTuples(); ++i)
        {
          for (int k = 0; k < 3; ++k)
          {
            nrm->SetComponent(i, k, -nrm->GetComponent(i, k));
          }
        }
        mesh->GetPointData()->Modified();
      });
    ExpectFreshAfter(f, "texture coordinates in place, then the polydata Modified()",
      [&]()
      {
        vtkDataArray* tc = mesh->GetPointData()->GetTCoords();
        for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
        {
          tc->SetComponent(i, 0, 1.01 * tc->GetComponent(i, 0) + 0.01);
        }
        mesh->Modified();
      });
  }
}

// The derivative scale (texture coordinates against dPdu/dPdv) must follow dPdu, dPdv and the
// texture coordinates changed in place. Each change moves the scale
// away from 1 and so turns the analytic normals (the factors are not powers of 2, whose change the
// estimate would undo to the bit). With the scale's freshness check removed, all 12 cases fail.
TEST(DisplacementMapFilter, ReExecutionAfterDerivativesModified)
{
  const Surface s = Torus();
  auto image = MakeHeightImage(s.Height, 128, 64);
  const int U = 48, V = 24;
  for (int mode : { vtkDisplacementMapFilter::Approximate, vtkDisplacementMapFilter::Exact })
  {
    for (bool useFloat : { false, true })
    {
      auto mesh = MakeMesh(s, U, V, true, useFloat);
      vtkNew<vtkDisplacementMapFilter> f;
      f->SetInputData(0, mesh);
      f->SetInputData(1, image);
      f->SetNormalMode(mode);
      f->SetMidlevel(0.5);
      f->SetScaleFactor(0.2);
      vtkPointData* pd = mesh->GetPointData();
      auto scaleInPlace = [](vtkDataArray* a, double factor)
      {
        for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
        {
          a->SetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents(),
            factor *
              a->GetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents()));
        }
      };
      ExpectFreshAfter(f, "dPdu scaled in place, then the array Modified()",
        [&]()
        {
          scaleInPlace(pd->GetArray("dPdu"), 1.3);
          pd->GetArray("dPdu")->Modified();
        });
      ExpectFreshAfter(f, "dPdv scaled in place, then the point data Modified()",
        [&]()
        {
          scaleInPlace(pd->GetArray("dPdv"), 0.7);
          pd->Modified();
        });
      ExpectFreshAfter(f, "texture coordinates stretched in place, then the array Modified()",
        [&]()
        {
          vtkDataArray* tc = pd->GetTCoords();
          for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
          {
            tc->SetComponent(i, 1, 1.5 * tc->GetComponent(i, 1));
          }
          tc->Modified();
        });
    }
  }
}

// Re-execution against every other way the input can change between executions: a new
// input object (which may reuse a freed one's address), a copy of another mesh into the same
// object, another active array, dPdu/dPdv appearing and going, another precision, another thread
// count, another piece.
TEST(DisplacementMapFilter, ReExecutionAfterInputReplaced)
{
  const Surface torus = Torus(), sphere = Sphere();
  auto image = MakeHeightImage(torus.Height, 128, 64);
  const int U = 48, V = 24;
  for (int mode : AllModes)
  {
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputData(1, image);
    f->SetNormalMode(mode);
    f->SetMidlevel(0.5);
    f->SetScaleFactor(0.2);
    auto mesh = MakeMesh(torus, U, V, false);
    f->SetInputData(0, mesh);
    // The first input and everything that refers to it freed before the next one is made, so
    // that its objects may come back at the same addresses.
    ExpectFreshAfter(f, "a new input object",
      [&]()
      {
        f->SetInputData(0, nullptr);
        f->GetOutput()->Initialize();
        mesh = nullptr;
        mesh = MakeMesh(sphere, U, V, false);
        f->SetInputData(0, mesh);
      });
    ExpectFreshAfter(f, "another mesh deep-copied into the input",
      [&]() { mesh->DeepCopy(MakeMesh(torus, U, V, false)); });
    ExpectFreshAfter(f, "another mesh shallow-copied into the input",
      [&]() { mesh->ShallowCopy(MakeMesh(sphere, U, V, false)); });
    ExpectFreshAfter(f, "other texture coordinates made active by name",
      [&]()
      {
        vtkNew<vtkDoubleArray> tc;
        tc->DeepCopy(mesh->GetPointData()->GetTCoords());
        tc->SetName("Stretched");
        for (vtkIdType i = 0; i < tc->GetNumberOfTuples(); ++i)
        {
          tc->SetComponent(i, 1, 0.9 * tc->GetComponent(i, 1) + 0.02);
        }
        mesh->GetPointData()->AddArray(tc);
        mesh->GetPointData()->SetActiveTCoords("Stretched");
      });
    ExpectFreshAfter(f, "other normals made active by name",
      [&]()
      {
        vtkNew<vtkDoubleArray> nrm;
        nrm->DeepCopy(mesh->GetPointData()->GetNormals());
        nrm->SetName("Reversed");
        for (vtkIdType i = 0; i < nrm->GetNumberOfValues(); ++i)
        {
          nrm->SetValue(i, -nrm->GetValue(i));
        }
        mesh->GetPointData()->AddArray(nrm);
        mesh->GetPointData()->SetActiveNormals("Reversed");
      });
    // dPdu/dPdv are read in the analytic modes only, tangents in all but None.
    const bool analytic =
      mode == vtkDisplacementMapFilter::Approximate || mode == vtkDisplacementMapFilter::Exact;
    auto withDerivatives = MakeMesh(sphere, U, V, true);
    if (analytic)
    {
      // (The analytic dPdu/dPdv differ from the fitted P_s, P_t, so the output moves.)
      ExpectFreshAfter(f, "dPdu and dPdv added",
        [&]()
        {
          mesh->GetPointData()->AddArray(withDerivatives->GetPointData()->GetArray("dPdu"));
          mesh->GetPointData()->AddArray(withDerivatives->GetPointData()->GetArray("dPdv"));
        });
      ExpectFreshAfter(f, "dPdu and dPdv removed",
        [&]()
        {
          mesh->GetPointData()->RemoveArray("dPdu");
          mesh->GetPointData()->RemoveArray("dPdv");
        });
    }
    ExpectFreshAfter(f, "a float mesh",
      [&]()
      {
        mesh = MakeMesh(torus, U, V, false, true);
        f->SetInputData(0, mesh);
      });
    if (mode != vtkDisplacementMapFilter::Input)
    {
      ExpectFreshAfter(f, "float input made double by a double tangent array",
        [&]()
        {
          vtkNew<vtkDoubleArray> tangents;
          tangents->DeepCopy(mesh->GetPointData()->GetTangents());
          mesh->GetPointData()->SetTangents(tangents);
        });
      // Back to float.
      ExpectFreshAfter(f, "double input made float again by a float tangent array",
        [&]()
        {
          vtkNew<vtkFloatArray> tangents;
          tangents->DeepCopy(mesh->GetPointData()->GetTangents());
          mesh->GetPointData()->SetTangents(tangents);
        });
    }
    ExpectFreshAfter(f, "another thread count",
      [&]()
      {
        vtkSMPTools::Initialize(1);
        f->Update();
        vtkSMPTools::Initialize(2);
        f->SetScaleFactor(0.25);
      });
    vtkSMPTools::Initialize(static_cast<int>(std::thread::hardware_concurrency()));
  }
}

// Re-execution against every setting changed between executions.
TEST(DisplacementMapFilter, ReExecutionAfterSettingsChange)
{
  const Surface s = Torus();
  const int U = 48, V = 24;
  // Two channels: the torus' heights, and another smooth field.
  auto first = MakeHeightImage(s.Height, 128, 64);
  auto second = MakeHeightImage([](double u, double v)
    { return 0.5 + 0.4 * std::sin(6 * Pi * u) * std::cos(2 * Pi * v); },
    128, 64);
  vtkNew<vtkImageData> image;
  image->SetDimensions(128, 64, 1);
  image->AllocateScalars(VTK_DOUBLE, 2);
  for (vtkIdType k = 0; k < 128 * 64; ++k)
  {
    image->GetPointData()->GetScalars()->SetComponent(
      k, 0, first->GetPointData()->GetScalars()->GetComponent(k, 0));
    image->GetPointData()->GetScalars()->SetComponent(
      k, 1, second->GetPointData()->GetScalars()->GetComponent(k, 0));
  }
  auto mesh = MakeMesh(s, U, V, false);
  // One seam duplicate 1e-4 off its twin: merged or not by SeamTolerance.
  vtkDataArray* pts = mesh->GetPoints()->GetData();
  pts->SetComponent(5 * (U + 1) + U, 2, pts->GetComponent(5 * (U + 1) + U, 2) + 1e-4);
  for (int mode : AllModes)
  {
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputData(0, mesh);
    f->SetInputData(1, image);
    f->SetNormalMode(mode);
    f->SetMidlevel(0.5);
    f->SetScaleFactor(0.2);
    for (int other : AllModes)
    {
      if (other != mode)
      {
        ExpectFreshAfter(f, "NormalMode", [&]() { f->SetNormalMode(other); });
      }
    }
    ExpectFreshAfter(f, "NormalMode back", [&]() { f->SetNormalMode(mode); });
    ExpectFreshAfter(f, "Interpolation", [&]() { f->SetInterpolationToCubic(); });
    ExpectFreshAfter(f, "Wrap", [&]() { f->SetWrapToClampToEdge(); });
    ExpectFreshAfter(f, "HeightComponent", [&]() { f->SetHeightComponent(1); });
    ExpectFreshAfter(f, "SeamTolerance", [&]() { f->SetSeamTolerance(1e-3); });
    ExpectFreshAfter(f, "MergeSeams off", [&]() { f->MergeSeamsOff(); });
    ExpectFreshAfter(f, "MergeSeams on", [&]() { f->MergeSeamsOn(); });
    ExpectFreshAfter(f, "SeamTolerance back", [&]() { f->SetSeamTolerance(1e-6); });
  }
}

// Pieces: each piece is a new input; nothing may leak from one piece to the next.
TEST(DisplacementMapFilter, ReExecutionAfterPieceChange)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(40);
  source->SetPhiResolution(20);
  vtkNew<SphereTCoords> tcoords;
  tcoords->SetInputConnection(source->GetOutputPort());
  auto image = MakeHeightImage(Sphere().Height, 64, 32);
  for (int mode : AllModes)
  {
    vtkNew<vtkDisplacementMapFilter> f;
    f->SetInputConnection(0, tcoords->GetOutputPort());
    f->SetInputData(1, image);
    f->SetNormalMode(mode);
    f->SetScaleFactor(0.05);
    f->SetMidlevel(0.5);
    f->UpdatePiece(0, 2, 0);
    auto first = vtkSmartPointer<vtkPolyData>::New();
    first->DeepCopy(f->GetOutput());
    f->UpdatePiece(1, 2, 0);
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    piece->DeepCopy(tcoords->GetOutput());
    auto fresh = Displace(piece, image, mode, 0.05, 0.5);
    ASSERT_EQ(first->GetNumberOfPoints(), piece->GetNumberOfPoints());
    EXPECT_TRUE(SameOutput(f->GetOutput(), fresh)) << "mode " << mode;
    EXPECT_FALSE(SameOutput(first, fresh)) << "mode " << mode;
  }
}
