! cvmesh.f90 - Fortran 2008 module `cvmesh`: the C API of include/cvmesh.h
! for Fortran programs.
!
! Two layers:
!  1. bind(C) interfaces to every public C function, with the status codes,
!     option keys and entity kinds as parameters. They are GENERATED from the
!     header into cvmesh_c_interfaces.inc by gen_interfaces.py (check.sh fails
!     when the two disagree). Handles are type(c_ptr); indices are 0-based.
!  2. A thin Fortran layer: the derived type cvm_mesh_t owns one handle (a
!     final procedure frees it) and has type-bound procedures taking
!     assumed-shape arrays (and cvm_sizing_t a sizing handle for refine()).
!     Coordinates are (2, n) arrays (C's (n, 2) rows);
!     connectivity is copied 1-based by default (optional base = 0 gives the
!     C numbering), with "none" (-1 in C: boundary neighbour, rejected point)
!     becoming 0. Every procedure takes an optional integer status; without
!     it, an error stops the program with the library's message.
!
! Do not copy a cvm_mesh_t with intrinsic assignment: both copies would own
! the same handle. Variables of the main program are not finalized; call
! destroy() there.
module cvmesh
    use, intrinsic :: iso_c_binding
    use, intrinsic :: iso_fortran_env, only: error_unit
    implicit none

    include 'cvmesh_c_interfaces.inc'

    interface
        function cvm_c_strlen(s) bind(C, name="strlen")
            import
            implicit none
            type(c_ptr), value :: s
            integer(c_size_t) :: cvm_c_strlen
        end function cvm_c_strlen
    end interface

    !> A cvmesh handle with its Fortran-friendly procedures.
    type :: cvm_mesh_t
        type(c_ptr) :: ptr = c_null_ptr
    contains
        procedure :: create => cvmf_create
        procedure :: destroy => cvmf_destroy
        procedure :: errmsg => cvmf_errmsg
        procedure :: set_points => cvmf_set_points
        procedure :: set_point_markers => cvmf_set_point_markers
        procedure :: set_segments => cvmf_set_segments
        procedure :: set_segment_markers => cvmf_set_segment_markers
        procedure :: set_point_attributes => cvmf_set_point_attributes
        procedure :: set_holes => cvmf_set_holes
        procedure :: set_regions => cvmf_set_regions
        procedure :: read => cvmf_read
        procedure :: set_option => cvmf_set_option
        procedure :: get_option => cvmf_get_option
        procedure :: triangulate => cvmf_triangulate
        procedure :: insert_points => cvmf_insert_points
        procedure :: refine => cvmf_refine
        procedure :: optimise_dual => cvmf_optimise_dual
        procedure :: check => cvmf_check
        procedure :: count => cvmf_count
        procedure :: get_points => cvmf_get_points
        procedure :: get_triangles => cvmf_get_triangles
        procedure :: get_edges => cvmf_get_edges
        procedure :: get_segments => cvmf_get_segments
        procedure :: get_neighbors => cvmf_get_neighbors
        procedure :: get_point_markers => cvmf_get_point_markers
        procedure :: get_segment_markers => cvmf_get_segment_markers
        procedure :: get_triangle_attributes => cvmf_get_triangle_attributes
        procedure :: get_point_attributes => cvmf_get_point_attributes
        procedure :: get_measure => cvmf_get_measure
        procedure :: set_weights => cvmf_set_weights
        procedure :: get_weights => cvmf_get_weights
        procedure :: get_dual_cells => cvmf_get_dual_cells
        procedure :: get_dual_areas => cvmf_get_dual_areas
        procedure :: get_dual_edge_lengths => cvmf_get_dual_edge_lengths
        procedure :: get_dual_vertices => cvmf_get_dual_vertices
        procedure :: write => cvmf_write
        final :: cvmf_final
    end type cvm_mesh_t

    !> A sizing handle (target edge length h(x, y)) for cvm_mesh_t%refine().
    type :: cvm_sizing_t
        type(c_ptr) :: ptr = c_null_ptr
    contains
        procedure :: create => cvmfs_create
        procedure :: destroy => cvmfs_destroy
        procedure :: errmsg => cvmfs_errmsg
        procedure :: set_uniform => cvmfs_set_uniform
        procedure :: add_point_source => cvmfs_add_point_source
        procedure :: add_line_source => cvmfs_add_line_source
        procedure :: set_boundary_grading => cvmfs_set_boundary_grading
        final :: cvmfs_final
    end type cvm_sizing_t

    private :: cvmf_report, cvmf_cells, cvmf_base, cvmf_c_path
    private :: cvmf_create, cvmf_destroy, cvmf_final, cvmf_errmsg, cvmf_set_points
    private :: cvmf_set_point_markers, cvmf_set_segments, cvmf_set_segment_markers
    private :: cvmf_set_holes, cvmf_set_regions, cvmf_read, cvmf_set_option, cvmf_get_option
    private :: cvmf_triangulate, cvmf_insert_points, cvmf_check, cvmf_count, cvmf_get_points
    private :: cvmf_get_triangles, cvmf_get_edges, cvmf_get_segments, cvmf_get_neighbors
    private :: cvmf_get_point_markers, cvmf_get_measure, cvmf_write, cvmf_refine
    private :: cvmf_set_weights, cvmf_get_dual_areas, cvmf_get_dual_edge_lengths
    private :: cvmf_get_dual_vertices, cvmf_doubles, cvmf_optimise_dual
    private :: cvmf_set_point_attributes, cvmf_get_segment_markers, cvmf_get_triangle_attributes
    private :: cvmf_get_point_attributes, cvmf_get_weights, cvmf_get_dual_cells, cvmf_markers
    private :: cvmfs_create, cvmfs_destroy, cvmfs_final, cvmfs_errmsg, cvmfs_set_uniform
    private :: cvmfs_add_point_source, cvmfs_add_line_source, cvmfs_report
    private :: cvmfs_set_boundary_grading

contains

    ! ---- strings ------------------------------------------------------------

    !> Fortran copy of a NUL-terminated C string ('' for a null pointer).
    function cvm_c_string(p) result(s)
        type(c_ptr), intent(in) :: p
        character(len=:), allocatable :: s
        character(kind=c_char), pointer :: chars(:)
        integer(c_size_t) :: n, i
        if (.not. c_associated(p)) then
            s = ''
            return
        end if
        n = cvm_c_strlen(p)
        call c_f_pointer(p, chars, [n])
        allocate (character(len=n) :: s)
        do i = 1, n
            s(i:i) = chars(i)
        end do
    end function cvm_c_string

    !> Fixed text of a status code, e.g. "out of memory".
    function cvm_status_text(status) result(s)
        integer, intent(in) :: status
        character(len=:), allocatable :: s
        s = cvm_c_string(cvm_status_str(int(status, c_int)))
    end function cvm_status_text

    !> Version of the linked library, "MAJOR.MINOR.PATCH".
    function cvm_version() result(s)
        character(len=:), allocatable :: s
        s = cvm_c_string(cvm_version_string())
    end function cvm_version

    !> .true. for an error status (1..99); .false. for OK and incomplete (>= 100).
    logical function cvm_is_error(status)
        integer, intent(in) :: status
        cvm_is_error = cvm_status_is_error(int(status, c_int)) /= 0
    end function cvm_is_error

    function cvmf_c_path(path) result(c)
        character(len=*), intent(in) :: path
        character(kind=c_char, len=:), allocatable :: c
        c = trim(path)//c_null_char
    end function cvmf_c_path

    ! Hand status s to the caller, or stop with the message when the caller
    ! gave no status argument and s is an error.
    subroutine cvmf_report(self, s, status, what)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int), intent(in) :: s
        integer, intent(out), optional :: status
        character(len=*), intent(in) :: what
        if (present(status)) then
            status = int(s)
        else if (cvm_status_is_error(s) /= 0) then
            write (error_unit, '(a, i0, a)') 'cvmesh: '//what//' failed with status ', s, &
                ' ('//cvm_status_text(int(s))//'): '//self%errmsg()
            error stop 1
        end if
    end subroutine cvmf_report

    ! ---- lifetime -------------------------------------------------------------

    !> Create the handle (freeing one already held).
    subroutine cvmf_create(self, status)
        class(cvm_mesh_t), intent(inout) :: self
        integer, intent(out), optional :: status
        integer(c_int) :: s
        call self%destroy()
        s = cvm_mesh_create(self%ptr)
        call cvmf_report(self, s, status, 'create')
    end subroutine cvmf_create

    !> Free the handle; safe to call twice.
    subroutine cvmf_destroy(self)
        class(cvm_mesh_t), intent(inout) :: self
        if (c_associated(self%ptr)) call cvm_mesh_free(self%ptr)
        self%ptr = c_null_ptr
    end subroutine cvmf_destroy

    subroutine cvmf_final(self)
        type(cvm_mesh_t), intent(inout) :: self
        call self%destroy()
    end subroutine cvmf_final

    !> Message of the last failing call, naming the offending input.
    function cvmf_errmsg(self) result(msg)
        class(cvm_mesh_t), intent(in) :: self
        character(len=:), allocatable :: msg
        msg = cvm_c_string(cvm_mesh_errmsg(self%ptr))
    end function cvmf_errmsg

    ! ---- input ----------------------------------------------------------------

    !> Input points, xy(1:2, i) = (x, y) of point i.
    subroutine cvmf_set_points(self, xy, status)
        class(cvm_mesh_t), intent(inout) :: self
        real(c_double), intent(in) :: xy(:, :)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_set_points(self%ptr, xy, size(xy, 2, c_size_t), int(size(xy, 1), c_int))
        call cvmf_report(self, s, status, 'set_points')
    end subroutine cvmf_set_points

    !> One integer marker per input point.
    subroutine cvmf_set_point_markers(self, markers, status)
        class(cvm_mesh_t), intent(inout) :: self
        integer(c_int32_t), intent(in) :: markers(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_set_point_markers(self%ptr, markers, size(markers, 1, c_size_t))
        call cvmf_report(self, s, status, 'set_point_markers')
    end subroutine cvmf_set_point_markers

    !> Constraint segments, segs(1:2, k) = point numbers of segment k,
    !> 1-based unless base = 0.
    subroutine cvmf_set_segments(self, segs, status, base)
        class(cvm_mesh_t), intent(inout) :: self
        integer(c_int32_t), intent(in) :: segs(:, :)
        integer, intent(out), optional :: status
        integer, intent(in), optional :: base
        integer(c_int) :: s
        integer(c_int32_t), allocatable :: zero_based(:, :)
        if (size(segs, 1) /= 2) then
            s = CVM_E_ARGUMENT
        else
            allocate (zero_based(2, size(segs, 2)))
            zero_based(:, :) = segs - cvmf_base(base)
            s = cvm_mesh_set_segments(self%ptr, zero_based, size(segs, 2, c_size_t))
        end if
        call cvmf_report(self, s, status, 'set_segments')
    end subroutine cvmf_set_segments

    !> One integer marker per segment.
    subroutine cvmf_set_segment_markers(self, markers, status)
        class(cvm_mesh_t), intent(inout) :: self
        integer(c_int32_t), intent(in) :: markers(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_set_segment_markers(self%ptr, markers, size(markers, 1, c_size_t))
        call cvmf_report(self, s, status, 'set_segment_markers')
    end subroutine cvmf_set_segment_markers

    !> Point attributes, attrs(1:a, i) = the a attributes of input point i
    !> (a >= 1; the same a for every point).
    subroutine cvmf_set_point_attributes(self, attrs, status)
        class(cvm_mesh_t), intent(inout) :: self
        real(c_double), intent(in) :: attrs(:, :)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_set_point_attributes(self%ptr, attrs, size(attrs, 2, c_size_t), &
                                          size(attrs, 1, c_size_t))
        call cvmf_report(self, s, status, 'set_point_attributes')
    end subroutine cvmf_set_point_attributes

    !> Hole seed points, xy(1:2, k).
    subroutine cvmf_set_holes(self, xy, status)
        class(cvm_mesh_t), intent(inout) :: self
        real(c_double), intent(in) :: xy(:, :)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        if (size(xy, 1) /= 2) then
            s = CVM_E_ARGUMENT
        else
            s = cvm_mesh_set_holes(self%ptr, xy, size(xy, 2, c_size_t))
        end if
        call cvmf_report(self, s, status, 'set_holes')
    end subroutine cvmf_set_holes

    !> Regions, r(1:4, k) = (x, y, attribute, max area).
    subroutine cvmf_set_regions(self, r, status)
        class(cvm_mesh_t), intent(inout) :: self
        real(c_double), intent(in) :: r(:, :)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        if (size(r, 1) /= 4) then
            s = CVM_E_ARGUMENT
        else
            s = cvm_mesh_set_regions(self%ptr, r, size(r, 2, c_size_t))
        end if
        call cvmf_report(self, s, status, 'set_regions')
    end subroutine cvmf_set_regions

    !> Replace the input by a Triangle .poly or .node file.
    subroutine cvmf_read(self, path, status)
        class(cvm_mesh_t), intent(inout) :: self
        character(len=*), intent(in) :: path
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_read(self%ptr, cvmf_c_path(path))
        call cvmf_report(self, s, status, 'read')
    end subroutine cvmf_read

    ! ---- options --------------------------------------------------------------

    !> Set option key (a CVM_OPT_* parameter).
    subroutine cvmf_set_option(self, key, value, status)
        class(cvm_mesh_t), intent(inout) :: self
        integer, intent(in) :: key
        real(c_double), intent(in) :: value
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_set_option(self%ptr, int(key, c_int), value)
        call cvmf_report(self, s, status, 'set_option')
    end subroutine cvmf_set_option

    !> Read option key.
    subroutine cvmf_get_option(self, key, value, status)
        class(cvm_mesh_t), intent(in) :: self
        integer, intent(in) :: key
        real(c_double), intent(out) :: value
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_get_option(value, self%ptr, int(key, c_int))
        call cvmf_report(self, s, status, 'get_option')
    end subroutine cvmf_get_option

    ! ---- meshing --------------------------------------------------------------

    !> (Constrained) Delaunay triangulation of the input.
    subroutine cvmf_triangulate(self, status)
        class(cvm_mesh_t), intent(inout) :: self
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_triangulate(self%ptr)
        call cvmf_report(self, s, status, 'triangulate')
    end subroutine cvmf_triangulate

    !> Insert points xy(1:2, k) into the triangulation. ids (optional, allocated
    !> here) receives the vertex number of each point, 1-based unless base = 0;
    !> a rejected point (outside, or closer than min_dist to a vertex) gets
    !> base - 1 (0 when 1-based).
    subroutine cvmf_insert_points(self, xy, status, ids, min_dist, base)
        class(cvm_mesh_t), intent(inout) :: self
        real(c_double), intent(in) :: xy(:, :)
        integer, intent(out), optional :: status
        integer(c_int32_t), allocatable, intent(out), optional :: ids(:)
        real(c_double), intent(in), optional :: min_dist
        integer, intent(in), optional :: base
        integer(c_int) :: s
        integer(c_int32_t), allocatable :: raw(:)
        real(c_double) :: d
        d = 0
        if (present(min_dist)) d = min_dist
        allocate (raw(size(xy, 2)))
        if (size(xy, 1) /= 2) then
            s = CVM_E_ARGUMENT
        else
            s = cvm_mesh_insert_points(raw, self%ptr, xy, size(xy, 2, c_size_t), d)
        end if
        if (present(ids)) then
            allocate (ids(size(raw)))
            ids(:) = raw + cvmf_base(base)
        end if
        call cvmf_report(self, s, status, 'insert_points')
    end subroutine cvmf_insert_points

    !> Refine with Steiner points until every triangle meets min_angle (degrees),
    !> max_area and the sizing: a uniform size, or a cvm_sizing_t. algorithm is
    !> CVM_ALGO_FRONTAL (default) or CVM_ALGO_DELAUNAY. The status may be
    !> CVM_INCOMPLETE_* (valid mesh, stopped early). Triangulates first when
    !> nothing is triangulated yet.
    subroutine cvmf_refine(self, status, algorithm, min_angle, max_area, size, sizing)
        class(cvm_mesh_t), intent(inout) :: self
        integer, intent(out), optional :: status
        integer, intent(in), optional :: algorithm
        real(c_double), intent(in), optional :: min_angle, max_area, size
        type(cvm_sizing_t), intent(in), optional :: sizing
        type(cvm_sizing_t) :: own
        type(c_ptr) :: sz
        integer(c_int) :: s, algo
        integer(c_size_t) :: ntri
        algo = CVM_ALGO_FRONTAL
        if (present(algorithm)) algo = int(algorithm, c_int)
        s = CVM_OK
        if (present(min_angle)) s = cvm_mesh_set_option(self%ptr, CVM_OPT_MIN_ANGLE_DEG, min_angle)
        if (s == CVM_OK .and. present(max_area)) &
            s = cvm_mesh_set_option(self%ptr, CVM_OPT_MAX_AREA, max_area)
        sz = c_null_ptr
        if (present(sizing)) sz = sizing%ptr
        if (s == CVM_OK .and. present(size)) then
            s = cvm_sizing_create(own%ptr)
            if (s == CVM_OK) s = cvm_sizing_set_uniform(own%ptr, size)
            if (s /= CVM_OK) then
                ! the message is the sizing handle's; report it on stderr if fatal
                if (.not. present(status)) write (error_unit, '(2a)') 'cvmesh: refine: ', own%errmsg()
            end if
            sz = own%ptr
        end if
        if (s == CVM_OK) s = cvm_mesh_count(ntri, self%ptr, CVM_ENT_TRIANGLE)
        if (s == CVM_OK .and. ntri == 0) s = cvm_mesh_triangulate(self%ptr)
        if (s == CVM_OK) s = cvm_mesh_refine(self%ptr, sz, algo)
        call own%destroy()
        call cvmf_report(self, s, status, 'refine')
    end subroutine cvmf_refine

    !> Move vertices and set power weights until every triangle contains its power
    !> vertex or is merged (cvm_mesh_optimise_dual). sizing (optional) sets the
    !> local sizes, else the mean edge length at each vertex; options such as
    !> CVM_OPT_DUAL_MAX_SWEEPS or CVM_OPT_TIME_LIMIT_S go through set_option.
    !> The status may be CVM_INCOMPLETE_* (a valid regular triangulation).
    subroutine cvmf_optimise_dual(self, status, sizing)
        class(cvm_mesh_t), intent(inout) :: self
        integer, intent(out), optional :: status
        type(cvm_sizing_t), intent(in), optional :: sizing
        type(c_ptr) :: sz
        sz = c_null_ptr
        if (present(sizing)) sz = sizing%ptr
        call cvmf_report(self, cvm_mesh_optimise_dual(self%ptr, sz), status, 'optimise_dual')
    end subroutine cvmf_optimise_dual

    !> Re-verify the mesh with exact predicates.
    subroutine cvmf_check(self, status)
        class(cvm_mesh_t), intent(inout) :: self
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_check(self%ptr)
        call cvmf_report(self, s, status, 'check')
    end subroutine cvmf_check

    ! ---- output ---------------------------------------------------------------

    !> Number of entities of a kind (a CVM_ENT_* parameter).
    function cvmf_count(self, kind, status) result(n)
        class(cvm_mesh_t), intent(in) :: self
        integer, intent(in) :: kind
        integer, intent(out), optional :: status
        integer(c_size_t) :: n
        integer(c_int) :: s
        n = 0
        s = cvm_mesh_count(n, self%ptr, int(kind, c_int))
        call cvmf_report(self, s, status, 'count')
    end function cvmf_count

    !> Vertex coordinates, xy(1:2, i) (allocated here).
    subroutine cvmf_get_points(self, xy, status)
        class(cvm_mesh_t), intent(in) :: self
        real(c_double), allocatable, intent(out) :: xy(:, :)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        integer(c_size_t) :: n
        n = 0
        s = cvm_mesh_count(n, self%ptr, CVM_ENT_VERTEX)
        if (s /= CVM_OK) n = 0
        allocate (xy(2, n))
        if (s == CVM_OK) s = cvm_mesh_copy_points(xy, 2*n, self%ptr)
        call cvmf_report(self, s, status, 'get_points')
    end subroutine cvmf_get_points

    integer function cvmf_base(base)
        integer, intent(in), optional :: base
        cvmf_base = 1
        if (present(base)) cvmf_base = base
    end function cvmf_base

    ! cells(1:width, k) of entity kind, allocated here, shifted to base.
    subroutine cvmf_cells(self, kind, width, cells, s, base)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int), intent(in) :: kind
        integer, intent(in) :: width
        integer(c_int32_t), allocatable, intent(out) :: cells(:, :)
        integer(c_int), intent(out) :: s
        integer, intent(in), optional :: base
        integer(c_size_t) :: n, len
        n = 0
        if (kind == CVM_ENT_NONE) then
            s = cvm_mesh_count(n, self%ptr, CVM_ENT_TRIANGLE)  ! neighbours
        else
            s = cvm_mesh_count(n, self%ptr, kind)
        end if
        if (s /= CVM_OK) n = 0
        allocate (cells(width, n))
        len = int(width, c_size_t)*n
        if (s == CVM_OK .and. kind == CVM_ENT_NONE) then
            s = cvm_mesh_copy_neighbors(cells, len, self%ptr)
        else if (s == CVM_OK) then
            s = cvm_mesh_copy_cells(cells, len, self%ptr, kind)
        end if
        if (s == CVM_OK) cells = cells + cvmf_base(base)
    end subroutine cvmf_cells

    !> Triangles, tri(1:3, k) counter-clockwise vertex numbers (1-based unless base = 0).
    subroutine cvmf_get_triangles(self, tri, status, base)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int32_t), allocatable, intent(out) :: tri(:, :)
        integer, intent(out), optional :: status
        integer, intent(in), optional :: base
        integer(c_int) :: s
        call cvmf_cells(self, CVM_ENT_TRIANGLE, 3, tri, s, base)
        call cvmf_report(self, s, status, 'get_triangles')
    end subroutine cvmf_get_triangles

    !> Edges, e(1:2, k) (1-based unless base = 0).
    subroutine cvmf_get_edges(self, e, status, base)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int32_t), allocatable, intent(out) :: e(:, :)
        integer, intent(out), optional :: status
        integer, intent(in), optional :: base
        integer(c_int) :: s
        call cvmf_cells(self, CVM_ENT_EDGE, 2, e, s, base)
        call cvmf_report(self, s, status, 'get_edges')
    end subroutine cvmf_get_edges

    !> Constrained edges of the output, seg(1:2, k) (1-based unless base = 0).
    subroutine cvmf_get_segments(self, seg, status, base)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int32_t), allocatable, intent(out) :: seg(:, :)
        integer, intent(out), optional :: status
        integer, intent(in), optional :: base
        integer(c_int) :: s
        call cvmf_cells(self, CVM_ENT_SEGMENT, 2, seg, s, base)
        call cvmf_report(self, s, status, 'get_segments')
    end subroutine cvmf_get_segments

    !> Neighbours, nb(j, k) = triangle across the edge opposite vertex j of
    !> triangle k (1-based unless base = 0; base - 1 on the boundary).
    subroutine cvmf_get_neighbors(self, nb, status, base)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int32_t), allocatable, intent(out) :: nb(:, :)
        integer, intent(out), optional :: status
        integer, intent(in), optional :: base
        integer(c_int) :: s
        call cvmf_cells(self, CVM_ENT_NONE, 3, nb, s, base)
        call cvmf_report(self, s, status, 'get_neighbors')
    end subroutine cvmf_get_neighbors

    ! Markers of every entity of kind, allocated here.
    subroutine cvmf_markers(self, kind, markers, s)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int), intent(in) :: kind
        integer(c_int32_t), allocatable, intent(out) :: markers(:)
        integer(c_int), intent(out) :: s
        integer(c_size_t) :: n
        n = 0
        s = cvm_mesh_count(n, self%ptr, kind)
        if (s /= CVM_OK) n = 0
        allocate (markers(n))
        if (s == CVM_OK) s = cvm_mesh_copy_markers(markers, n, self%ptr, kind)
    end subroutine cvmf_markers

    !> Marker of each vertex (allocated here).
    subroutine cvmf_get_point_markers(self, markers, status)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int32_t), allocatable, intent(out) :: markers(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        call cvmf_markers(self, CVM_ENT_VERTEX, markers, s)
        call cvmf_report(self, s, status, 'get_point_markers')
    end subroutine cvmf_get_point_markers

    !> Marker of each output segment, in the order of get_segments() (allocated
    !> here); a piece of a split input segment keeps that segment's marker.
    subroutine cvmf_get_segment_markers(self, markers, status)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int32_t), allocatable, intent(out) :: markers(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        call cvmf_markers(self, CVM_ENT_SEGMENT, markers, s)
        call cvmf_report(self, s, status, 'get_segment_markers')
    end subroutine cvmf_get_segment_markers

    !> Regional attribute of each triangle, in the order of get_triangles()
    !> (allocated here; 0 without regions).
    subroutine cvmf_get_triangle_attributes(self, attr, status)
        class(cvm_mesh_t), intent(in) :: self
        real(c_double), allocatable, intent(out) :: attr(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        call cvmf_doubles(self, CVM_ENT_TRIANGLE, 1, 4, attr, s)
        call cvmf_report(self, s, status, 'get_triangle_attributes')
    end subroutine cvmf_get_triangle_attributes

    !> Point attributes of each vertex, attrs(1:a, i) (allocated here; a = 0
    !> without attributes; a vertex added by refinement gets interpolated values).
    subroutine cvmf_get_point_attributes(self, attrs, status)
        class(cvm_mesh_t), intent(in) :: self
        real(c_double), allocatable, intent(out) :: attrs(:, :)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        integer(c_size_t) :: n, na, got
        real(c_double), allocatable :: buf(:)
        n = 0
        s = cvm_mesh_count(n, self%ptr, CVM_ENT_VERTEX)
        na = 0
        got = 0
        ! the attribute count is reported by a call that succeeds: grow until one does
        do while (s == CVM_OK .or. s == CVM_E_BUFFER_TOO_SMALL)
            if (allocated(buf)) deallocate (buf)
            allocate (buf(max(na*n, 1_c_size_t)))
            s = cvm_mesh_copy_point_attributes(buf, na*n, got, self%ptr)
            if (s /= CVM_E_BUFFER_TOO_SMALL .or. na > 4096) exit
            na = max(1_c_size_t, 2*na)
        end do
        if (s /= CVM_OK) got = 0
        allocate (attrs(got, n))
        if (got > 0) attrs(:, :) = reshape(buf(1:got*n), [got, n])
        call cvmf_report(self, s, status, 'get_point_attributes')
    end subroutine cvmf_get_point_attributes

    !> A quality measure (a CVM_MEASURE_* parameter).
    subroutine cvmf_get_measure(self, which, value, status)
        class(cvm_mesh_t), intent(inout) :: self
        integer, intent(in) :: which
        real(c_double), intent(out) :: value
        integer, intent(out), optional :: status
        integer(c_int) :: s
        value = 0
        s = cvm_mesh_get_measure(value, self%ptr, int(which, c_int))
        call cvmf_report(self, s, status, 'get_measure')
    end subroutine cvmf_get_measure

    ! ---- weights and the power (Voronoi) dual ---------------------------------

    !> Power weight of every vertex (size = vertex count), making the
    !> triangulation regular; an empty array removes the weights.
    subroutine cvmf_set_weights(self, w, status)
        class(cvm_mesh_t), intent(inout) :: self
        real(c_double), intent(in) :: w(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        real(c_double) :: none(1)
        if (size(w) == 0) then
            none = 0
            s = cvm_mesh_set_weights(self%ptr, none, 0_c_size_t)
        else
            s = cvm_mesh_set_weights(self%ptr, w, size(w, 1, c_size_t))
        end if
        call cvmf_report(self, s, status, 'set_weights')
    end subroutine cvmf_set_weights

    !> Power weight of each vertex (allocated here; 0 when none were set).
    subroutine cvmf_get_weights(self, w, status)
        class(cvm_mesh_t), intent(in) :: self
        real(c_double), allocatable, intent(out) :: w(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        call cvmf_doubles(self, CVM_ENT_VERTEX, 1, 5, w, s)
        call cvmf_report(self, s, status, 'get_weights')
    end subroutine cvmf_get_weights

    !> Dual (power/Voronoi) cell polygon of every vertex, restricted to the
    !> domain, counter-clockwise (cvm_mesh_copy_dual_cells): vertex v's cell
    !> has the corners xy(1:2, first(v) : first(v+1)-1), first(1:nv+1)
    !> 1-based (0-based with base = 0: corners first(v)+1 .. first(v+1) of
    !> xy). Each cell has its own copy of its corners. Allocated here.
    subroutine cvmf_get_dual_cells(self, first, xy, status, base)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int32_t), allocatable, intent(out) :: first(:)
        real(c_double), allocatable, intent(out) :: xy(:, :)
        integer, intent(out), optional :: status
        integer, intent(in), optional :: base
        integer(c_int) :: s
        integer(c_size_t) :: n, k
        n = 0
        k = 0
        s = cvm_mesh_count(n, self%ptr, CVM_ENT_VERTEX)
        if (s /= CVM_OK) n = 0
        allocate (first(n + 1))
        first = 0
        if (s == CVM_OK) s = cvm_mesh_copy_dual_cell_offsets(first, n + 1, self%ptr)
        if (s == CVM_OK) k = int(first(n + 1), c_size_t)
        allocate (xy(2, k))
        if (s == CVM_OK .and. k > 0) s = cvm_mesh_copy_dual_cells(xy, 2*k, self%ptr)
        if (s == CVM_OK) first = first + cvmf_base(base)
        call cvmf_report(self, s, status, 'get_dual_cells')
    end subroutine cvmf_get_dual_cells

    ! width doubles per entity of kind, allocated here, filled by which:
    ! 1 dual areas, 2 dual edge lengths, 3 dual vertices, 4 triangle
    ! attributes, 5 weights.
    subroutine cvmf_doubles(self, kind, width, which, v, s)
        class(cvm_mesh_t), intent(in) :: self
        integer(c_int), intent(in) :: kind
        integer, intent(in) :: width, which
        real(c_double), allocatable, intent(out) :: v(:)
        integer(c_int), intent(out) :: s
        integer(c_size_t) :: n
        n = 0
        s = cvm_mesh_count(n, self%ptr, kind)
        if (s /= CVM_OK) n = 0
        n = n*int(width, c_size_t)
        allocate (v(n))
        if (s /= CVM_OK) return
        select case (which)
        case (1)
            s = cvm_mesh_copy_dual_areas(v, n, self%ptr)
        case (2)
            s = cvm_mesh_copy_dual_edge_lengths(v, n, self%ptr)
        case (4)
            s = cvm_mesh_copy_triangle_attributes(v, n, self%ptr)
        case (5)
            s = cvm_mesh_copy_weights(v, n, self%ptr)
        case default
            s = cvm_mesh_copy_dual_vertices(v, n, self%ptr)
        end select
    end subroutine cvmf_doubles

    !> Dual (power/Voronoi) cell area of each vertex, within the domain.
    subroutine cvmf_get_dual_areas(self, area, status)
        class(cvm_mesh_t), intent(in) :: self
        real(c_double), allocatable, intent(out) :: area(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        call cvmf_doubles(self, CVM_ENT_VERTEX, 1, 1, area, s)
        call cvmf_report(self, s, status, 'get_dual_areas')
    end subroutine cvmf_get_dual_areas

    !> Dual edge length of each edge, in the order of get_edges().
    subroutine cvmf_get_dual_edge_lengths(self, length, status)
        class(cvm_mesh_t), intent(in) :: self
        real(c_double), allocatable, intent(out) :: length(:)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        call cvmf_doubles(self, CVM_ENT_EDGE, 1, 2, length, s)
        call cvmf_report(self, s, status, 'get_dual_edge_lengths')
    end subroutine cvmf_get_dual_edge_lengths

    !> Power vertex (circumcentre without weights) of each triangle, xy(1:2, k).
    subroutine cvmf_get_dual_vertices(self, xy, status)
        class(cvm_mesh_t), intent(in) :: self
        real(c_double), allocatable, intent(out) :: xy(:, :)
        integer, intent(out), optional :: status
        integer(c_int) :: s
        real(c_double), allocatable :: flat(:)
        call cvmf_doubles(self, CVM_ENT_TRIANGLE, 2, 3, flat, s)
        allocate (xy(2, size(flat)/2))
        if (size(flat) > 0) xy(:, :) = reshape(flat, [2, size(flat)/2])
        call cvmf_report(self, s, status, 'get_dual_vertices')
    end subroutine cvmf_get_dual_vertices

    !> Write the mesh; the format follows the extension (.vtu, .msh, .node, .svg).
    subroutine cvmf_write(self, path, status)
        class(cvm_mesh_t), intent(inout) :: self
        character(len=*), intent(in) :: path
        integer, intent(out), optional :: status
        integer(c_int) :: s
        s = cvm_mesh_write(self%ptr, cvmf_c_path(path))
        call cvmf_report(self, s, status, 'write')
    end subroutine cvmf_write

    ! ---- sizing -----------------------------------------------------------------

    subroutine cvmfs_report(self, s, status, what)
        class(cvm_sizing_t), intent(in) :: self
        integer(c_int), intent(in) :: s
        integer, intent(out), optional :: status
        character(len=*), intent(in) :: what
        if (present(status)) then
            status = int(s)
        else if (cvm_status_is_error(s) /= 0) then
            write (error_unit, '(a, i0, a)') 'cvmesh: sizing '//what//' failed with status ', s, &
                ' ('//cvm_status_text(int(s))//'): '//self%errmsg()
            error stop 1
        end if
    end subroutine cvmfs_report

    !> Create the sizing handle (no source: no size bound).
    subroutine cvmfs_create(self, status)
        class(cvm_sizing_t), intent(inout) :: self
        integer, intent(out), optional :: status
        call self%destroy()
        call cvmfs_report(self, cvm_sizing_create(self%ptr), status, 'create')
    end subroutine cvmfs_create

    !> Free the handle; safe to call twice.
    subroutine cvmfs_destroy(self)
        class(cvm_sizing_t), intent(inout) :: self
        if (c_associated(self%ptr)) call cvm_sizing_free(self%ptr)
        self%ptr = c_null_ptr
    end subroutine cvmfs_destroy

    subroutine cvmfs_final(self)
        type(cvm_sizing_t), intent(inout) :: self
        call self%destroy()
    end subroutine cvmfs_final

    !> Message of the last failing call on the sizing handle.
    function cvmfs_errmsg(self) result(msg)
        class(cvm_sizing_t), intent(in) :: self
        character(len=:), allocatable :: msg
        msg = cvm_c_string(cvm_sizing_errmsg(self%ptr))
    end function cvmfs_errmsg

    !> Uniform target edge length h.
    subroutine cvmfs_set_uniform(self, h, status)
        class(cvm_sizing_t), intent(inout) :: self
        real(c_double), intent(in) :: h
        integer, intent(out), optional :: status
        call cvmfs_report(self, cvm_sizing_set_uniform(self%ptr, h), status, 'set_uniform')
    end subroutine cvmfs_set_uniform

    !> Point source: h(p) = h + growth |p - (x, y)|.
    subroutine cvmfs_add_point_source(self, x, y, h, growth, status)
        class(cvm_sizing_t), intent(inout) :: self
        real(c_double), intent(in) :: x, y, h, growth
        integer, intent(out), optional :: status
        call cvmfs_report(self, cvm_sizing_add_point_source(self%ptr, x, y, h, growth), status, &
                          'add_point_source')
    end subroutine cvmfs_add_point_source

    !> Line source: h(p) = h + growth dist(p, segment (x0, y0)-(x1, y1)).
    subroutine cvmfs_add_line_source(self, x0, y0, x1, y1, h, growth, status)
        class(cvm_sizing_t), intent(inout) :: self
        real(c_double), intent(in) :: x0, y0, x1, y1, h, growth
        integer, intent(out), optional :: status
        call cvmfs_report(self, cvm_sizing_add_line_source(self%ptr, x0, y0, x1, y1, h, growth), &
                          status, 'add_line_source')
    end subroutine cvmfs_add_line_source

    !> Cap the size by l(e) + g dist(p, e) over the boundary and constrained edges e
    !> of the mesh being refined or optimised (g > 0; 0 turns it off).
    subroutine cvmfs_set_boundary_grading(self, g, status)
        class(cvm_sizing_t), intent(inout) :: self
        real(c_double), intent(in) :: g
        integer, intent(out), optional :: status
        call cvmfs_report(self, cvm_sizing_set_boundary_grading(self%ptr, g), status, &
                          'set_boundary_grading')
    end subroutine cvmfs_set_boundary_grading

end module cvmesh
