"""Write the interoperability seed files of this directory with the real
clients: meshio (every .vtu encoding, legacy .vtk, Gmsh 2.2 and 4.1 ASCII and
binary) and, when it is installed, VTK (the XML writer in each data mode,
compressed or not, both header types and byte orders; the legacy writers).

The mesh is the unit square split into four triangles around its centre (a
Delaunay triangulation, so cvm_mesh_read() rebuilds it), its four sides as
line cells with markers 1..4, point data "weight" and "marker", and cell data
"marker". Run: build/venv/bin/python tests/data/interop/make_interop.py
"""
import os
import sys

import meshio
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PTS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0]], dtype=float)
TRI = np.array([[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
LIN = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
WEIGHT = np.array([0.0, 0.0, 0.0, 0.0, 0.01])
PMARK = np.array([1, 1, 1, 1, 0], dtype=np.int32)


def meshio_files():
    cells = [("triangle", TRI), ("line", LIN)]
    mesh = meshio.Mesh(PTS, cells, point_data={"weight": WEIGHT, "marker": PMARK},
                       cell_data={"marker": [np.zeros(4, dtype=np.int32),
                                             np.array([1, 2, 3, 4], dtype=np.int32)]})
    out = lambda n: os.path.join(HERE, n)
    meshio.vtu.write(out("square_meshio_ascii.vtu"), mesh, binary=False)
    meshio.vtu.write(out("square_meshio_base64.vtu"), mesh, binary=True, compression=None)
    meshio.vtu.write(out("square_meshio_zlib.vtu"), mesh, binary=True, compression="zlib")
    meshio.vtk.write(out("square_meshio_ascii.vtk"), mesh, binary=False)
    meshio.vtk.write(out("square_meshio_binary.vtk"), mesh, binary=True)
    # Gmsh: markers as physical tags, with names
    gcells = [("line", LIN), ("triangle", TRI)]
    dim_tags = np.array([[1, 1], [1, 2], [1, 3], [1, 4], [2, 1]])
    gmesh = meshio.Mesh(PTS[:, :2].copy(), gcells, point_data={"gmsh:dim_tags": dim_tags}, cell_data={
        "gmsh:physical": [np.array([1, 2, 3, 4]), np.array([7, 7, 7, 7])],
        "gmsh:geometrical": [np.array([1, 2, 3, 4]), np.array([1, 1, 1, 1])]},
        field_data={"bottom": np.array([1, 1]), "right": np.array([2, 1]),
                    "top": np.array([3, 1]), "left": np.array([4, 1]),
                    "inside": np.array([7, 2])})
    # a domain: boundary lines with physical tags 1..4, a point with tag 9
    dom = meshio.Mesh(np.array([[0, 0], [2, 0], [2, 1], [0, 1], [1, 0.5]], float),
                      [("line", LIN), ("vertex", np.array([[4]]))],
                      cell_data={"gmsh:physical": [np.array([1, 2, 3, 4]), np.array([9])],
                                 "gmsh:geometrical": [np.array([1, 2, 3, 4]), np.array([1])]},
                      field_data={"bottom": np.array([1, 1]), "right": np.array([2, 1]),
                                  "top": np.array([3, 1]), "left": np.array([4, 1]),
                                  "centre": np.array([9, 0])})
    meshio.write(out("domain_meshio_22.msh"), dom, file_format="gmsh22", binary=False)
    meshio.write(out("domain_meshio_22b.msh"), dom, file_format="gmsh22", binary=True)
    for ver, tag in (("gmsh22", "22"), ("gmsh", "41")):
        for binary in (False, True):
            meshio.write(out("square_meshio_%s%s.msh" % (tag, "b" if binary else "")), gmesh,
                         file_format=ver, binary=binary)


def vtk_files():
    try:
        import vtk
    except ImportError:
        print("vtk not installed: only the meshio files were written")
        return
    pts = vtk.vtkPoints()
    for p in PTS:
        pts.InsertNextPoint(*p)
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(pts)
    for t in TRI:
        grid.InsertNextCell(vtk.VTK_TRIANGLE, 3, [int(i) for i in t])
    for e in LIN:
        grid.InsertNextCell(vtk.VTK_LINE, 2, [int(i) for i in e])
    w = vtk.vtkDoubleArray()
    w.SetName("weight")
    for x in WEIGHT:
        w.InsertNextValue(x)
    grid.GetPointData().AddArray(w)
    m = vtk.vtkIntArray()
    m.SetName("marker")
    for x in [0, 0, 0, 0, 1, 2, 3, 4]:
        m.InsertNextValue(x)
    grid.GetCellData().AddArray(m)
    out = lambda n: os.path.join(HERE, n)
    modes = [("ascii", lambda wr: wr.SetDataModeToAscii()),
             ("binary", lambda wr: (wr.SetDataModeToBinary(), wr.SetCompressorTypeToNone())),
             ("binary_zlib", lambda wr: (wr.SetDataModeToBinary(), wr.SetCompressorTypeToZLib())),
             ("appended_raw", lambda wr: (wr.SetDataModeToAppended(), wr.EncodeAppendedDataOff(),
                                          wr.SetCompressorTypeToNone())),
             ("appended_base64", lambda wr: (wr.SetDataModeToAppended(), wr.EncodeAppendedDataOn(),
                                             wr.SetCompressorTypeToNone())),
             ("appended_zlib", lambda wr: (wr.SetDataModeToAppended(), wr.EncodeAppendedDataOff(),
                                           wr.SetCompressorTypeToZLib())),
             ("appended_zlib_h32_be", lambda wr: (wr.SetDataModeToAppended(),
                                                  wr.EncodeAppendedDataOff(),
                                                  wr.SetCompressorTypeToZLib(),
                                                  wr.SetHeaderTypeToUInt32(),
                                                  wr.SetByteOrderToBigEndian()))]
    for name, setup in modes:
        wr = vtk.vtkXMLUnstructuredGridWriter()
        wr.SetInputData(grid)
        setup(wr)
        wr.SetFileName(out("square_vtk_%s.vtu" % name))
        wr.Write()
    for name, binary in (("ascii", False), ("binary", True)):
        wr = vtk.vtkUnstructuredGridWriter()
        wr.SetInputData(grid)
        if binary:
            wr.SetFileTypeToBinary()
        wr.SetFileName(out("square_vtk_%s.vtk" % name))
        wr.Write()
    poly = vtk.vtkPolyData()
    poly.SetPoints(pts)
    polys = vtk.vtkCellArray()
    for t in TRI:
        polys.InsertNextCell(3, [int(i) for i in t])
    poly.SetPolys(polys)
    wr = vtk.vtkPolyDataWriter()
    wr.SetInputData(poly)
    wr.SetFileName(out("square_vtk_polydata.vtk"))
    wr.Write()


if __name__ == "__main__":
    meshio_files()
    vtk_files()
    sys.exit(0)
