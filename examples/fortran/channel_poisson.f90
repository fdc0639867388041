! channel_poisson.f90 - a legacy-solver-style program using the cvmesh module:
! mesh a 3 x 1 channel, read back coordinates, 1-based connectivity and the
! dual (Voronoi) cell areas and dual edge lengths, check them against its own
! circumcentric construction, and solve the Poisson problem -lap(u) = f with a
! vertex-centred finite-volume scheme on the dual cells by Jacobi iteration,
! against a manufactured solution
!     u(x, y) = sin(pi x / 3) sin(pi y) + x y / 10,   f = (10 pi^2 / 9) sin(pi x / 3) sin(pi y).
! Prints the error against u and stops with a failure status when it is too
! large, so `make check` notices a broken mesh.
!
! The mesh is refined with cvm_mesh_refine (frontal-Delaunay, target size 0.8 h,
! minimum angle 28 degrees); a library built without refinement
! (CVM_E_UNSUPPORTED) gets a staggered grid of interior points inserted with
! cvm_mesh_insert_points instead.
!
! Finite volumes on the Voronoi dual: for each interior vertex i,
!     sum over edges ij of (|dual edge ij| / |edge ij|) (u_i - u_j) = f_i |cell i|.
program channel_poisson
    use, intrinsic :: iso_c_binding, only: c_double, c_int32_t
    use cvmesh
    implicit none

    real(c_double), parameter :: pi = 3.14159265358979323846_c_double
    real(c_double), parameter :: length = 3, height = 1, h = 0.1_c_double
    integer, parameter :: iterations = 800
    ! the discretisation error is O(h^2): about 1e-2 here; a wrong dual gives O(1)
    real(c_double), parameter :: tolerance = 2.5_c_double*h**2

    type(cvm_mesh_t) :: mesh
    real(c_double), allocatable :: bxy(:, :), ixy(:, :), xy(:, :)
    integer(c_int32_t), allocatable :: segs(:, :), bmark(:), tri(:, :), edges(:, :), mark(:), ids(:)
    real(c_double), allocatable :: u(:), unew(:), rhs(:), area(:), own_area(:), dual_len(:)
    real(c_double), allocatable :: diag(:), num(:), w(:)
    logical, allocatable :: dirichlet(:)
    integer :: nb, nv, nt, ne, i, k, it, status, p, q
    real(c_double) :: err_max, err_l2, total_area, c(2), e(2), nrm(2), d, le, min_angle

    ! ---- the channel as a PSLG: boundary points every h, one closed loop ----
    call boundary(bxy)
    nb = size(bxy, 2)
    allocate (segs(2, nb), bmark(nb))
    do i = 1, nb
        segs(:, i) = [i, mod(i, nb) + 1]     ! 1-based point numbers
    end do
    bmark = 1

    call mesh%create()
    call mesh%set_points(bxy)
    call mesh%set_point_markers(bmark)
    call mesh%set_segments(segs)              ! base 1 by default
    call mesh%set_segment_markers(bmark)
    call mesh%triangulate(status)
    if (status /= CVM_OK) then
        print '(a, i0, 2a)', 'triangulate failed: status ', status, ': ', mesh%errmsg()
        error stop 1
    end if

    ! ---- refine to size h; without refinement, insert a staggered lattice ----
    call mesh%refine(status, algorithm=CVM_ALGO_FRONTAL, min_angle=28.0_c_double, size=0.8_c_double*h)
    if (status == CVM_E_UNSUPPORTED) then
        call lattice(ixy)
        call mesh%insert_points(ixy, status, ids=ids, min_dist=0.3_c_double*h)
        print '(a, i0, a, i0, a)', 'no refinement: inserted ', count(ids > 0), ' of ', size(ids), &
            ' lattice points'
    end if
    if (status /= CVM_OK) then
        print '(a, i0, 2a)', 'meshing failed: status ', status, ': ', mesh%errmsg()
        error stop 1
    end if
    call mesh%get_measure(CVM_MEASURE_MIN_ANGLE_DEG, min_angle)
    print '(a, f6.2, a)', 'smallest angle ', min_angle, ' degrees'
    call mesh%check()

    ! ---- read the mesh back: coordinates (2, nv), triangles (3, nt) and edges
    !      (2, ne) 1-based, and the dual: cell areas (nv), dual edge lengths (ne) ----
    call mesh%get_points(xy)
    call mesh%get_triangles(tri)
    call mesh%get_edges(edges)
    call mesh%get_point_markers(mark)
    call mesh%get_dual_areas(area)
    call mesh%get_dual_edge_lengths(dual_len)
    nv = size(xy, 2)
    nt = size(tri, 2)
    ne = size(edges, 2)
    print '(a, i0, a, i0, a, i0, a)', 'mesh: ', nv, ' vertices, ', nt, ' triangles, ', ne, ' edges'

    ! ---- the same cell areas from the circumcentres: the circumcentre c of a
    !      triangle gives each end of an edge |edge| * d / 4, d the signed distance
    !      from the edge midpoint to c (positive towards the triangle) ----
    allocate (own_area(nv))
    own_area = 0
    do k = 1, nt
        c = circumcentre(xy(:, tri(1, k)), xy(:, tri(2, k)), xy(:, tri(3, k)))
        do i = 1, 3
            p = tri(mod(i, 3) + 1, k)
            q = tri(mod(i + 1, 3) + 1, k)
            e = xy(:, q) - xy(:, p)
            le = norm2(e)
            nrm = [-e(2), e(1)]/le    ! left normal: towards the third vertex (ccw)
            d = dot_product(c - 0.5_c_double*(xy(:, p) + xy(:, q)), nrm)
            own_area(p) = own_area(p) + le*d/4
            own_area(q) = own_area(q) + le*d/4
        end do
    end do
    total_area = sum(area)
    print '(a, f12.9, a, es9.2)', 'sum of dual cell areas ', total_area, &
        ', largest difference to the circumcentric construction ', maxval(abs(area - own_area))

    ! ---- edge coefficients |dual edge| / |edge| ----
    allocate (w(ne), diag(nv), num(nv), rhs(nv), u(nv), unew(nv), dirichlet(nv))
    diag = 0
    do k = 1, ne
        p = edges(1, k)
        q = edges(2, k)
        w(k) = dual_len(k)/norm2(xy(:, q) - xy(:, p))
        diag(p) = diag(p) + w(k)
        diag(q) = diag(q) + w(k)
    end do

    ! ---- finite volumes: sum_j w_ij (u_i - u_j) = f_i area_i; u = exact on the boundary ----
    dirichlet = mark /= 0
    do i = 1, nv
        rhs(i) = source(xy(1, i), xy(2, i))*area(i)
        u(i) = 0
        if (dirichlet(i)) u(i) = exact(xy(1, i), xy(2, i))
    end do
    do it = 1, iterations
        num = 0
        do k = 1, ne
            p = edges(1, k)
            q = edges(2, k)
            num(p) = num(p) + w(k)*u(q)
            num(q) = num(q) + w(k)*u(p)
        end do
        where (dirichlet)
            unew = u
        elsewhere
            unew = (rhs + num)/diag
        end where
        u = unew
        if (mod(it, 100) == 0) then
            call errors(err_max, err_l2)
            print '(a, i4, a, es10.3, a, es10.3)', 'jacobi ', it, ': max error ', err_max, &
                ', L2 error ', err_l2
        end if
    end do

    call errors(err_max, err_l2)
    print '(a, es10.3, a, es10.3)', 'final max error ', err_max, ', L2 error ', err_l2
    call mesh%destroy()
    if (abs(total_area - length*height) > 1.0e-9_c_double) error stop 'dual cell areas do not sum to the domain area'
    if (maxval(abs(area - own_area)) > 1.0e-12_c_double) error stop 'dual cell areas differ from the circumcentres'
    if (.not. (err_max < tolerance)) error stop 'error above tolerance'
    print '(a)', 'channel_poisson: ok'

contains

    pure real(c_double) function exact(x, y)
        real(c_double), intent(in) :: x, y
        exact = sin(pi*x/3)*sin(pi*y) + x*y/10
    end function exact

    pure real(c_double) function source(x, y)
        real(c_double), intent(in) :: x, y
        source = (10*pi**2/9)*sin(pi*x/3)*sin(pi*y)
    end function source

    pure function circumcentre(a, b, c) result(o)
        real(c_double), intent(in) :: a(2), b(2), c(2)
        real(c_double) :: o(2), bx, by, cx, cy, dd
        bx = b(1) - a(1)
        by = b(2) - a(2)
        cx = c(1) - a(1)
        cy = c(2) - a(2)
        dd = 2*(bx*cy - by*cx)
        o(1) = a(1) + (cy*(bx*bx + by*by) - by*(cx*cx + cy*cy))/dd
        o(2) = a(2) + (bx*(cx*cx + cy*cy) - cx*(bx*bx + by*by))/dd
    end function circumcentre

    ! Counter-clockwise boundary points of the channel, spacing h.
    subroutine boundary(pts)
        real(c_double), allocatable, intent(out) :: pts(:, :)
        integer :: nx, ny, j, n
        nx = nint(length/h)
        ny = nint(height/h)
        allocate (pts(2, 2*(nx + ny)))
        n = 0
        do j = 0, nx - 1
            n = n + 1
            pts(:, n) = [j*length/nx, 0.0_c_double]
        end do
        do j = 0, ny - 1
            n = n + 1
            pts(:, n) = [length, j*height/ny]
        end do
        do j = nx, 1, -1
            n = n + 1
            pts(:, n) = [j*length/nx, height]
        end do
        do j = ny, 1, -1
            n = n + 1
            pts(:, n) = [0.0_c_double, j*height/ny]
        end do
    end subroutine boundary

    ! Interior points: rows dy = h sqrt(3)/2 apart, odd rows shifted by h/2.
    subroutine lattice(pts)
        real(c_double), allocatable, intent(out) :: pts(:, :)
        integer :: rows, cols, j, l, n
        real(c_double) :: dy, x
        rows = nint(height/(h*sqrt(3.0_c_double)/2))
        dy = height/rows
        cols = nint(length/h)
        allocate (pts(2, (rows - 1)*(cols + 1)))
        n = 0
        do j = 1, rows - 1
            do l = 0, cols
                x = (l + 0.5_c_double*mod(j, 2))*h
                if (x < 0.4_c_double*h .or. x > length - 0.4_c_double*h) cycle
                n = n + 1
                pts(:, n) = [x, j*dy]
            end do
        end do
        pts = pts(:, 1:n)
    end subroutine lattice

    subroutine errors(emax, el2)
        real(c_double), intent(out) :: emax, el2
        integer :: v
        real(c_double) :: diff
        emax = 0
        el2 = 0
        do v = 1, nv
            diff = abs(u(v) - exact(xy(1, v), xy(2, v)))
            emax = max(emax, diff)
            el2 = el2 + diff**2*area(v)
        end do
        el2 = sqrt(el2)
    end subroutine errors

end program channel_poisson
