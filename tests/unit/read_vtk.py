#!/usr/bin/env python3
"""Reads a .vtp file with VTK's own reader, or a .pvd collection with
Python's XML parser and each listed file with VTK, and prints what it found
as lines that vtk_files_test.cpp compares with the mesh it wrote:

  points N                  then N lines: p X Y Z
  verts|lines|polys N       then N lines: c I J K ...
  array NAME TYPE COMPONENTS  then one line per point: v A [B C]
  dataset STEP FILE POINTS  (for a .pvd: each listed file, in file order)

Floats are printed with repr, which reads back exactly (nan, inf, -0.0).
Exits non-zero, saying why, when VTK reports an error or the file is no
collection. Test-only: needs python3-vtk9 (scripts/install-deps)."""
import os
import sys
import xml.etree.ElementTree as ET

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def read_polydata(path):
    reader = vtkXMLPolyDataReader()
    errors = []
    # VTK reports bad files through its error events, not exceptions.
    reader.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
    reader.SetFileName(path)
    reader.Update()
    if errors or reader.GetErrorCode() != 0:
        sys.exit("%s: VTK could not read it" % path)
    return reader.GetOutput()


def number(value):
    return repr(value) if isinstance(value, float) else str(value)


def dump_polydata(path):
    data = read_polydata(path)
    points = data.GetPoints()
    n = data.GetNumberOfPoints()
    print("points", n)
    for i in range(n):
        print("p", *(repr(c) for c in points.GetPoint(i)))
    for kind, cells in (("verts", data.GetVerts()), ("lines", data.GetLines()), ("polys", data.GetPolys())):
        print(kind, cells.GetNumberOfCells())
        offsets = cells.GetOffsetsArray()
        connectivity = cells.GetConnectivityArray()
        for c in range(cells.GetNumberOfCells()):
            begin, end = int(offsets.GetValue(c)), int(offsets.GetValue(c + 1))
            print("c", *(int(connectivity.GetValue(k)) for k in range(begin, end)))
    point_data = data.GetPointData()
    for a in range(point_data.GetNumberOfArrays()):
        array = point_data.GetArray(a)
        components = array.GetNumberOfComponents()
        print("array", array.GetName(), array.GetDataTypeAsString().replace(" ", "_"), components)
        for i in range(array.GetNumberOfTuples()):
            print("v", *(number(array.GetComponent(i, k)) if array.GetDataType() in (10, 11)
                         else str(int(array.GetComponent(i, k))) for k in range(components)))


def dump_collection(path):
    root = ET.parse(path).getroot()
    if root.tag != "VTKFile" or root.get("type") != "Collection" or root.find("Collection") is None:
        sys.exit("%s: no ParaView collection" % path)
    folder = os.path.dirname(path)
    for dataset in root.find("Collection").findall("DataSet"):
        listed = dataset.get("file")
        data = read_polydata(os.path.join(folder, listed))
        print("dataset", dataset.get("timestep"), listed, data.GetNumberOfPoints())


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: read_vtk.py FILE.vtp|FILE.pvd")
    if sys.argv[1].endswith(".pvd"):
        dump_collection(sys.argv[1])
    else:
        dump_polydata(sys.argv[1])
