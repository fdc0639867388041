! test_cvmesh.f90 - tests of the Fortran module cvmesh: status codes and
! messages, 1-based and 0-based copies, (2, n) coordinates, version agreement.
! Run by bindings/fortran/check.sh; prints "N passed, N failed" and exits
! non-zero on a failure.
program test_cvmesh
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use cvmesh
    implicit none
    integer :: passed = 0, failed = 0

    call test_version()
    call test_square_one_based()
    call test_zero_based_copies()
    call test_bad_segment_names_the_segment()
    call test_nonfinite_point()
    call test_option_range()
    call test_insert_points()
    call test_status_text()
    call test_raw_interfaces()
    call test_refine_and_dual()
    call test_segment_markers_follow_their_segments()
    call test_triangle_attributes_of_two_regions()
    call test_weights_and_point_attributes_round_trip()
    call test_dual_cells_tile_the_areas()

    print '(a, i0, a, i0, a)', 'fortran: ', passed, ' passed, ', failed, ' failed'
    if (failed > 0) error stop 1

contains

    subroutine expect(ok, what)
        logical, intent(in) :: ok
        character(len=*), intent(in) :: what
        if (ok) then
            passed = passed + 1
        else
            failed = failed + 1
            print '(2a)', 'FAILED: ', what
        end if
    end subroutine expect

    ! Bitwise equality of two doubles (exact comparisons are intended here).
    elemental logical function same(a, b)
        real(c_double), intent(in) :: a, b
        same = transfer(a, 1_c_int64_t) == transfer(b, 1_c_int64_t)
    end function same

    subroutine square(mesh)
        type(cvm_mesh_t), intent(inout) :: mesh
        real(c_double) :: xy(2, 4)
        integer(c_int32_t) :: segs(2, 4)
        xy = reshape([0d0, 0d0, 1d0, 0d0, 1d0, 1d0, 0d0, 1d0], [2, 4])
        segs = reshape([1, 2, 2, 3, 3, 4, 4, 1], [2, 4])
        call mesh%create()
        call mesh%set_points(xy)
        call mesh%set_segments(segs)
    end subroutine square

    subroutine test_version()
        call expect(cvm_version_number() == CVM_VERSION_NUMBER_H, 'version number agrees with the header')
        call expect(len(cvm_version()) >= 5, 'version string')
    end subroutine test_version

    subroutine test_square_one_based()
        type(cvm_mesh_t) :: mesh
        integer(c_int32_t), allocatable :: tri(:, :), nb(:, :), seg(:, :)
        real(c_double), allocatable :: pts(:, :)
        integer :: status
        call square(mesh)
        call mesh%triangulate(status)
        call expect(status == CVM_OK, 'square triangulates')
        call mesh%get_points(pts)
        call expect(all(shape(pts) == [2, 4]), 'points are (2, n)')
        call expect(same(pts(1, 2), 1d0) .and. same(pts(2, 2), 0d0), 'point 2 is (1, 0)')
        call mesh%get_triangles(tri)
        call expect(all(shape(tri) == [3, 2]), 'two triangles (3, m)')
        call expect(minval(tri) == 1 .and. maxval(tri) == 4, 'triangles are 1-based')
        call mesh%get_neighbors(nb)
        call expect(count(nb == 0) == 4 .and. count(nb == 1) == 1 .and. count(nb == 2) == 1, &
                    'neighbours 1-based, 0 on the boundary')
        call mesh%get_segments(seg)
        call expect(size(seg, 2) == 4 .and. minval(seg) == 1, 'segments 1-based')
        call expect(mesh%count(CVM_ENT_EDGE) == 5, 'five edges')
        call mesh%check(status)
        call expect(status == CVM_OK, 'check passes')
        call mesh%destroy()
        call mesh%destroy()
        call expect(.not. c_associated(mesh%ptr), 'destroy twice is safe')
    end subroutine test_square_one_based

    subroutine test_zero_based_copies()
        type(cvm_mesh_t) :: mesh
        integer(c_int32_t), allocatable :: tri(:, :), nb(:, :)
        call square(mesh)
        call mesh%triangulate()
        call mesh%get_triangles(tri, base=0)
        call expect(minval(tri) == 0 .and. maxval(tri) == 3, 'base=0 gives C numbering')
        call mesh%get_neighbors(nb, base=0)
        call expect(count(nb == -1) == 4, 'base=0 neighbours: -1 on the boundary')
    end subroutine test_zero_based_copies

    subroutine test_bad_segment_names_the_segment()
        type(cvm_mesh_t) :: mesh
        real(c_double) :: xy(2, 3)
        integer(c_int32_t) :: segs(2, 2)
        integer :: status
        xy = reshape([0d0, 0d0, 1d0, 0d0, 0d0, 1d0], [2, 3])
        segs = reshape([1, 2, 2, 9], [2, 2])
        call mesh%create()
        call mesh%set_points(xy)
        call mesh%set_segments(segs)
        call mesh%triangulate(status)
        call expect(status == CVM_E_INPUT_INDEX, 'bad index gives CVM_E_INPUT_INDEX')
        call expect(cvm_is_error(status), 'it is an error')
        call expect(index(mesh%errmsg(), 'segment 1') > 0, 'message names segment 1 (0-based): ' &
                    //mesh%errmsg())
    end subroutine test_bad_segment_names_the_segment

    subroutine test_nonfinite_point()
        type(cvm_mesh_t) :: mesh
        real(c_double) :: xy(2, 3)
        integer :: status
        xy = reshape([0d0, 0d0, 1d0, 0d0, 0d0, 1d0], [2, 3])
        xy(2, 3) = ieee_value(1d0, ieee_quiet_nan)
        call mesh%create()
        call mesh%set_points(xy, status)
        call expect(status == CVM_E_INPUT_NONFINITE, 'NaN gives CVM_E_INPUT_NONFINITE')
        call expect(index(mesh%errmsg(), 'point 2') > 0, 'message names point 2: '//mesh%errmsg())
    end subroutine test_nonfinite_point

    subroutine test_option_range()
        type(cvm_mesh_t) :: mesh
        real(c_double) :: v
        integer :: status
        call mesh%create()
        call mesh%set_option(CVM_OPT_MIN_ANGLE_DEG, 90d0, status)
        call expect(status == CVM_E_OPTION_RANGE, 'option out of range')
        call mesh%set_option(CVM_OPT_SEED, 7d0)
        call mesh%get_option(CVM_OPT_SEED, v)
        call expect(same(v, 7d0), 'option read back')
    end subroutine test_option_range

    subroutine test_insert_points()
        type(cvm_mesh_t) :: mesh
        real(c_double) :: p(2, 3)
        integer(c_int32_t), allocatable :: ids(:)
        integer :: status
        p = reshape([0.5d0, 0.5d0, 5d0, 5d0, 0.25d0, 0.5d0], [2, 3])
        call square(mesh)
        call mesh%insert_points(p, status)
        call expect(status == CVM_E_STATE, 'insert before triangulate is a state error')
        call mesh%triangulate()
        call mesh%insert_points(p, status, ids=ids)
        call expect(status == CVM_OK, 'insert_points')
        call expect(all(ids == [5, 0, 6]), 'ids 1-based, 0 for the rejected point')
        call expect(mesh%count(CVM_ENT_VERTEX) == 6, 'six vertices')
    end subroutine test_insert_points

    subroutine test_status_text()
        call expect(cvm_status_text(CVM_E_NOMEM) == 'out of memory', 'status text')
        call expect(.not. cvm_is_error(CVM_INCOMPLETE_CANCELLED), 'incomplete is not an error')
    end subroutine test_status_text

    subroutine test_raw_interfaces()
        type(c_ptr) :: m
        type(cvm_bounds) :: b
        integer(c_size_t) :: n
        integer(c_int32_t) :: cells(6)
        integer(c_int) :: s
        real(c_double) :: xy(2, 4)
        xy = reshape([0d0, 0d0, 1d0, 0d0, 1d0, 1d0, 0d0, 1d0], [2, 4])
        call expect(cvm_mesh_create(m) == CVM_OK, 'raw create')
        call expect(cvm_mesh_set_points(m, xy, 4_c_size_t, 2_c_int) == CVM_OK, 'raw set_points')
        call expect(cvm_mesh_triangulate(m) == CVM_OK, 'raw triangulate')
        s = cvm_mesh_count(n, m, CVM_ENT_TRIANGLE)
        call expect(s == CVM_OK .and. n == 2, 'raw count')
        call expect(cvm_mesh_copy_cells(cells, 5_c_size_t, m, CVM_ENT_TRIANGLE) == &
                    CVM_E_BUFFER_TOO_SMALL, 'raw copy into a short buffer')
        call expect(cvm_mesh_copy_cells(cells, 6_c_size_t, m, CVM_ENT_TRIANGLE) == CVM_OK, 'raw copy')
        call expect(minval(cells) == 0 .and. maxval(cells) == 3, 'raw copy is 0-based')
        call cvm_mesh_free(m)
        s = cvm_option_bounds(b, CVM_OPT_MIN_ANGLE_DEG)
        call expect(s == CVM_OK .and. b%lo <= b%def .and. b%def <= b%hi, 'option bounds struct')
    end subroutine test_raw_interfaces

    subroutine test_refine_and_dual()
        type(cvm_mesh_t) :: mesh
        type(cvm_sizing_t) :: sizing
        real(c_double), allocatable :: area(:), dlen(:), dv(:, :), w(:)
        integer(c_int32_t), allocatable :: e(:, :), tri(:, :)
        real(c_double) :: amin
        integer :: status
        call square(mesh)
        call mesh%refine(status, min_angle=25d0, size=0.1d0)
        if (status == CVM_E_UNSUPPORTED) return
        call expect(status == CVM_OK, 'refine with a uniform size')
        call mesh%get_measure(CVM_MEASURE_MIN_ANGLE_DEG, amin)
        call expect(amin >= 25d0 - 1d-9, 'refined mesh meets the angle')
        call mesh%get_dual_areas(area)
        call expect(size(area) == mesh%count(CVM_ENT_VERTEX), 'one dual area per vertex')
        call expect(abs(sum(area) - 1d0) < 1d-12, 'dual areas sum to the domain area')
        call mesh%get_edges(e)
        call mesh%get_dual_edge_lengths(dlen)
        call expect(size(dlen) == size(e, 2) .and. all(dlen >= 0), 'one dual length per edge')
        call mesh%get_triangles(tri)
        call mesh%get_dual_vertices(dv)
        call expect(all(shape(dv) == [2, size(tri, 2)]), 'one dual vertex per triangle')
        allocate (w(size(area)))
        w = 0
        call mesh%set_weights(w(1:3), status)
        call expect(status == CVM_E_ARGUMENT, 'weights must match the vertex count')
        call mesh%set_weights(w, status)
        call expect(status == CVM_OK, 'zero weights')
        call sizing%create()
        call sizing%set_uniform(-1d0, status)
        call expect(status == CVM_E_ARGUMENT, 'bad uniform size')
        call expect(index(sizing%errmsg(), 'uniform size') > 0, 'sizing errors name the source')
        call sizing%set_uniform(0.05d0)
        call sizing%add_point_source(0d0, 0d0, 0.01d0, 0.2d0)
        call mesh%refine(status, sizing=sizing)
        call expect(status == CVM_OK, 'refine with a sizing handle')
        call sizing%set_boundary_grading(-1d0, status)
        call expect(status == CVM_E_ARGUMENT, 'bad boundary grading')
        call sizing%set_boundary_grading(0.3d0, status)
        call expect(status == CVM_OK, 'boundary grading')
        call mesh%optimise_dual(status, sizing=sizing)
        call expect(status == CVM_OK, 'optimise the dual')
        call mesh%get_measure(CVM_MEASURE_DUAL_NONCOMPLIANT_PCT, amin)
        call expect(amin <= 0d0, 'every triangle compliant after optimise_dual')
        call mesh%check(status)
        call expect(status == CVM_OK, 'optimised mesh checks')
        call sizing%destroy()
    end subroutine test_refine_and_dual

    subroutine test_segment_markers_follow_their_segments()
        type(cvm_mesh_t) :: mesh
        integer(c_int32_t), allocatable :: seg(:, :), mark(:)
        real(c_double), allocatable :: p(:, :)
        integer :: status, k
        logical :: on_side
        call square(mesh)
        call mesh%set_segment_markers([11, 12, 13, 14])
        call mesh%refine(status, max_area=0.01d0)
        call expect(status == CVM_OK, 'refine with segment markers')
        call mesh%get_segments(seg)
        call mesh%get_segment_markers(mark, status)
        call expect(status == CVM_OK .and. size(mark) == size(seg, 2) .and. size(mark) > 4, &
                    'one marker per output segment')
        call mesh%get_points(p)
        on_side = .true.
        do k = 1, size(mark)
            ! segment 11 is y = 0, 12 is x = 1, 13 is y = 1, 14 is x = 0: exact
            select case (mark(k))
            case (11)
                on_side = on_side .and. same(p(2, seg(1, k)), 0d0) .and. same(p(2, seg(2, k)), 0d0)
            case (12)
                on_side = on_side .and. same(p(1, seg(1, k)), 1d0) .and. same(p(1, seg(2, k)), 1d0)
            case (13)
                on_side = on_side .and. same(p(2, seg(1, k)), 1d0) .and. same(p(2, seg(2, k)), 1d0)
            case (14)
                on_side = on_side .and. same(p(1, seg(1, k)), 0d0) .and. same(p(1, seg(2, k)), 0d0)
            case default
                on_side = .false.
            end select
        end do
        call expect(on_side, 'each piece lies on the input segment whose marker it carries')
        call mesh%destroy()
    end subroutine test_segment_markers_follow_their_segments

    subroutine test_triangle_attributes_of_two_regions()
        type(cvm_mesh_t) :: mesh
        real(c_double) :: xy(2, 6), r(4, 2)
        integer(c_int32_t) :: segs(2, 7)
        integer(c_int32_t), allocatable :: tri(:, :)
        real(c_double), allocatable :: attr(:), p(:, :)
        integer :: status, k
        logical :: ok
        xy = reshape([0d0, 0d0, 0.5d0, 0d0, 1d0, 0d0, 1d0, 1d0, 0.5d0, 1d0, 0d0, 1d0], [2, 6])
        segs = reshape([1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 1, 2, 5], [2, 7])
        r = reshape([0.25d0, 0.5d0, 1d0, -1d0, 0.75d0, 0.5d0, 2d0, -1d0], [4, 2])
        call mesh%create()
        call mesh%set_points(xy)
        call mesh%set_segments(segs)
        call mesh%set_regions(r)
        call mesh%refine(status, max_area=0.02d0)
        call expect(status == CVM_OK, 'two regions refine')
        call mesh%get_triangles(tri)
        call mesh%get_points(p)
        call mesh%get_triangle_attributes(attr, status)
        call expect(status == CVM_OK .and. size(attr) == size(tri, 2), 'one attribute per triangle')
        ok = .true.
        do k = 1, size(attr)
            if (all(p(1, tri(:, k)) <= 0.5d0)) then
                ok = ok .and. same(attr(k), 1d0)
            else
                ok = ok .and. same(attr(k), 2d0) .and. all(p(1, tri(:, k)) >= 0.5d0)
            end if
        end do
        call expect(ok, 'attribute 1 left of x = 0.5, 2 right of it')
        call mesh%destroy()
    end subroutine test_triangle_attributes_of_two_regions

    subroutine test_weights_and_point_attributes_round_trip()
        type(cvm_mesh_t) :: mesh
        real(c_double) :: a(2, 4)
        real(c_double), allocatable :: w(:), back(:, :), none(:, :)
        integer :: status, k
        logical :: ok
        a = reshape([1d0, -1d0, 2d0, -2d0, 3d0, -3d0, 4d0, -4d0], [2, 4])
        call square(mesh)
        call mesh%get_point_attributes(none, status)
        call expect(status == CVM_OK .and. size(none, 1) == 0, 'no point attributes before any')
        call mesh%set_point_attributes(a, status)
        call expect(status == CVM_OK, 'set_point_attributes')
        call mesh%triangulate()
        call mesh%get_point_attributes(back, status)
        ok = status == CVM_OK .and. all(shape(back) == [2, 4])
        if (ok) ok = all(same(back, a))
        call expect(ok, 'point attributes come back (2, n) as set')
        call mesh%get_weights(w, status)
        call expect(status == CVM_OK .and. size(w) == 4 .and. all(same(w, 0d0)), 'weights 0 before any')
        call mesh%set_weights([0.01d0, 0.02d0, 0.03d0, 0.04d0])
        call mesh%get_weights(w)
        ok = size(w) == 4
        do k = 1, min(4, size(w))
            ok = ok .and. same(w(k), 0.01d0*k)
        end do
        call expect(ok, 'weights come back bit for bit')
        call mesh%destroy()
    end subroutine test_weights_and_point_attributes_round_trip

    subroutine test_dual_cells_tile_the_areas()
        type(cvm_mesh_t) :: mesh
        integer(c_int32_t), allocatable :: first(:), first0(:)
        real(c_double), allocatable :: c(:, :), c0(:, :), area(:)
        real(c_double) :: shoelace, worst
        integer :: status, v, i, j
        call square(mesh)
        call mesh%refine(status, min_angle=25d0, max_area=0.01d0)
        call mesh%get_dual_cells(first, c, status)
        call expect(status == CVM_OK, 'get_dual_cells')
        call mesh%get_dual_areas(area)
        call expect(size(first) == size(area) + 1 .and. first(1) == 1 .and. &
                    first(size(first)) == size(c, 2) + 1, 'cell offsets 1-based, nv + 1 of them')
        worst = 0
        do v = 1, size(area)
            shoelace = 0
            do i = first(v), first(v + 1) - 1
                j = i + 1
                if (j == first(v + 1)) j = first(v)
                shoelace = shoelace + c(1, i)*c(2, j) - c(1, j)*c(2, i)
            end do
            worst = max(worst, abs(shoelace/2 - area(v)))
        end do
        call expect(worst <= 1d-14, 'shoelace area of each cell = its dual area')
        call expect(abs(sum(area) - 1d0) <= 1d-12, 'the cells tile the unit square')
        call mesh%get_dual_cells(first0, c0, base=0)
        call expect(all(first0 == first - 1) .and. all(same(c0, c)), 'base = 0 gives the C offsets')
        call mesh%destroy()
    end subroutine test_dual_cells_tile_the_areas

end program test_cvmesh
