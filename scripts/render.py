#!/usr/bin/python3
"""render.py: a roof .vtp (bin/wskel --format vtp) to a PNG, with VTK offscreen.

usage: xvfb-run -a /usr/bin/python3 scripts/render.py ROOF.vtp OUT.png
           [--size 1200x900] [--azimuth 30] [--elevation 35]
The roof is coloured by height (the skeleton time), lit, with its edges drawn
dark, on a white background: the figure style of README.md.
"""
import argparse
import sys

import vtk


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("vtp")
    ap.add_argument("png")
    ap.add_argument("--size", default="1200x900")
    ap.add_argument("--azimuth", type=float, default=30.0)
    ap.add_argument("--elevation", type=float, default=35.0)
    args = ap.parse_args()
    w, h = (int(v) for v in args.size.split("x"))

    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(args.vtp)
    reader.Update()
    poly = reader.GetOutput()
    if poly.GetNumberOfPoints() == 0:
        sys.stderr.write("render.py: %s: no points\n" % args.vtp)
        return 1
    # Colour by height: the z coordinate is the skeleton time.
    elev = vtk.vtkElevationFilter()
    elev.SetInputData(poly)
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
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().EdgeVisibilityOn()
    actor.GetProperty().SetEdgeColor(0.15, 0.15, 0.15)
    actor.GetProperty().SetLineWidth(1.0)

    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    ren.AddActor(actor)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(w, h)
    ren.ResetCamera()
    cam = ren.GetActiveCamera()
    cam.Azimuth(args.azimuth)
    cam.Elevation(args.elevation)
    cam.OrthogonalizeViewUp()
    ren.ResetCamera()
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
