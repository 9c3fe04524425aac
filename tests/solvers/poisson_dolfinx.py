#!/usr/bin/python3
"""The L-shape Poisson problem of poisson.py with DOLFINx (python3-dolfinx 0.5, which reads Gmsh
files through python3-gmsh): a documented example whose figures are in docs/manual.md, "Feeding a
solver"; not part of the test suite (DOLFINx takes seconds just to start).

  poisson_dolfinx.py FILE.msh 1|2

Prints the L2 error of u, the area of cell region 1000000000 (the domain) and the lengths of facet regions 1, 2, 3.
"""
import sys

import numpy as np
import ufl
import gmsh
from mpi4py import MPI
from dolfinx import fem
from dolfinx.io import gmshio
import dolfinx.fem.petsc  # noqa: F401  (LinearProblem)

# DOLFINx's own Gmsh reader. (Debian's 0.5.2 gmshio.read_from_msh returns an undefined name, so
# this does what it means to: load the file into Gmsh's model and convert that.)
gmsh.initialize()
gmsh.merge(sys.argv[1])
mesh, cells, facets = gmshio.model_to_mesh(gmsh.model, MPI.COMM_WORLD, 0, gdim=2)
gmsh.finalize()
order = int(sys.argv[2])
V = fem.FunctionSpace(mesh, ("Lagrange", order))
x = ufl.SpatialCoordinate(mesh)
pi = ufl.pi
ue = ufl.sin(pi * x[0]) * ufl.cos(pi * x[1]) + x[0] * x[1]
f = 2 * pi**2 * ufl.sin(pi * x[0]) * ufl.cos(pi * x[1])
gx = pi * ufl.cos(pi * x[0]) * ufl.cos(pi * x[1]) + x[1]
gy = -pi * ufl.sin(pi * x[0]) * ufl.sin(pi * x[1]) + x[0]
dx = ufl.Measure("dx", domain=mesh, subdomain_data=cells)
ds = ufl.Measure("ds", domain=mesh, subdomain_data=facets)
u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
a = ufl.inner(ufl.grad(u), ufl.grad(v)) * dx
L = f * v * dx + gx * v * ds(2) + gy * v * ds(3)
u_d = fem.Function(V)
u_d.interpolate(lambda X: np.sin(np.pi * X[0]) * np.cos(np.pi * X[1]) + X[0] * X[1])
dofs = fem.locate_dofs_topological(V, mesh.topology.dim - 1, facets.find(1))
problem = fem.petsc.LinearProblem(a, L, bcs=[fem.dirichletbc(u_d, dofs)],
                                  petsc_options={"ksp_type": "preonly", "pc_type": "lu"})
uh = problem.solve()
one = fem.Constant(mesh, 1.0)
scalar = lambda form: mesh.comm.allreduce(fem.assemble_scalar(fem.form(form)), op=MPI.SUM)
err = np.sqrt(scalar((uh - ue) ** 2 * dx(metadata={"quadrature_degree": 10})))
print(f"RESULT err {err:.4e} area {scalar(one * dx(1000000000)):.12g} lengths {[round(scalar(one * ds(k)), 12) for k in (1, 2, 3)]}")
