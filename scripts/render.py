#!/usr/bin/python3
"""render.py: a roof .vtp (bin/wskel --format vtp) to a PNG, with VTK offscreen.

usage: xvfb-run -a /usr/bin/python3 scripts/render.py ROOF.vtp OUT.png
           [--size 1200x900] [--azimuth -60] [--elevation 40] [--zoom 1]
The roof is coloured by height (the skeleton time), lit, with the polygon's
boundary and the skeleton's arcs (the .vtp's lines) drawn dark, on a white
background: the figure style of README.md.  The faces are triangulated
first (vtkTriangleFilter, ear cutting): a roof face of a polygon with holes
or reflex vertices is rarely convex, and VTK draws a polygon cell as a
triangle fan, which is wrong for a non-convex one.
"""
import argparse
import math
import sys

import vtk


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("vtp")
    ap.add_argument("png")
    ap.add_argument("--size", default="1200x900")
    ap.add_argument("--azimuth", type=float, default=-60.0,
                    help="camera direction around the vertical, degrees from +x")
    ap.add_argument("--elevation", type=float, default=40.0,
                    help="camera angle above the ground plane, degrees")
    ap.add_argument("--zoom", type=float, default=1.0,
                    help="camera zoom after fitting the roof into the view")
    args = ap.parse_args()
    w, h = (int(v) for v in args.size.split("x"))

    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(args.vtp)
    reader.Update()
    poly = reader.GetOutput()
    if poly.GetNumberOfPoints() == 0:
        sys.stderr.write("render.py: %s: no points\n" % args.vtp)
        return 1
    # The faces alone (the lines are drawn apart), as triangles.
    faces = vtk.vtkPolyData()
    faces.SetPoints(poly.GetPoints())
    faces.SetPolys(poly.GetPolys())
    tri = vtk.vtkTriangleFilter()
    tri.SetInputData(faces)
    # Colour by height: the z coordinate is the skeleton time.
    elev = vtk.vtkElevationFilter()
    elev.SetInputConnection(tri.GetOutputPort())
    b = poly.GetBounds()
    elev.SetLowPoint(0, 0, b[4])
    elev.SetHighPoint(0, 0, b[5] if b[5] > b[4] else b[4] + 1)
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputConnection(elev.GetOutputPort())
    normals.SplittingOff()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.6, 0.0)
    lut.Build()
    mapper.SetLookupTable(lut)
    # Map heights to colours per pixel: interpolating the vertices' colours in
    # RGB across a face passes through hues that are no height.
    mapper.InterpolateScalarsBeforeMappingOn()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    # The boundary and the arcs: the lines of the .vtp, dark, over the faces.
    lines = vtk.vtkPolyData()
    lines.SetPoints(poly.GetPoints())
    lines.SetLines(poly.GetLines())
    lmapper = vtk.vtkPolyDataMapper()
    lmapper.SetInputData(lines)
    lmapper.ScalarVisibilityOff()
    lmapper.SetResolveCoincidentTopologyToPolygonOffset()
    lactor = vtk.vtkActor()
    lactor.SetMapper(lmapper)
    lactor.GetProperty().SetColor(0.1, 0.1, 0.1)
    lactor.GetProperty().SetLineWidth(1.5)
    lactor.GetProperty().LightingOff()

    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    ren.AddActor(actor)
    ren.AddActor(lactor)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(w, h)
    # The camera looks at the roof's centre from the direction azimuth
    # (degrees around the vertical from +x) and elevation (degrees above the
    # ground plane), z up, so the roof stands on the ground as a roof does.
    cx, cy, cz = (b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2
    dist = 3.0 * max(b[1] - b[0], b[3] - b[2], b[5] - b[4], 1e-300)
    az, el = math.radians(args.azimuth), math.radians(args.elevation)
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(cx, cy, cz)
    cam.SetPosition(cx + dist * math.cos(el) * math.cos(az), cy + dist * math.cos(el) * math.sin(az),
                    cz + dist * math.sin(el))
    cam.SetViewUp(0, 0, 1)
    ren.ResetCamera()
    cam.Zoom(args.zoom)
    win.Render()
    shot = vtk.vtkWindowToImageFilter()
    shot.SetInput(win)
    shot.ReadFrontBufferOff()
    shot.Update()
    png = vtk.vtkPNGWriter()
    png.SetFileName(args.png)
    png.SetInputConnection(shot.GetOutputPort())
    png.Write()
    print("wrote", args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
