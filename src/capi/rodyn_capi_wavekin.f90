!> librodyn's external water kinematics (MoorDyn v2's MoorDyn_ExternalWaveKin*;
!> docs/capi.md): for a MoorDyn file with WaveKin 1 a host gives the water's velocity and
!> acceleration at MoorDyn's places, and rodyn's steps use them at the nodes of the lines
!> and of the free points in place of waves, held from one MoorDyn_ExternalWaveKinSet to
!> the next, at the still water level (rodyn_water: water_set_external). MoorDyn's
!> places, in its order: the nodes of each line (0 to N) in turn, the nodes of each rod,
!> every point, the ground, every body. Values at the places rodyn has no water load on
!> (fixed points, rods, bodies) are accepted and not used: rodyn's rods are fixed, a free
!> body with WaveKin 1 is refused when read.
module rodyn_capi_wavekin
   use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_double, c_f_pointer, &
                                          c_associated
   use, intrinsic :: iso_fortran_env, only: error_unit
   use rodyn_kinds, only: wp
   use rodyn_mesh, only: mesh_node
   use rodyn_water, only: water_set_external
   use rodyn_capi_system, only: md_system_t, system_body_state, system_point_x
   use rodyn_capi_handles, only: capi_system_t, system_of, md_success, md_invalid_value
   implicit none
   private
   public :: md_wk_init, md_wk_coords, md_wk_set

contains

   !> The number of MoorDyn's places (module header) of an initialised system.
   pure integer function places(s) result(n)
      type(md_system_t), intent(in) :: s    !< the system
      n = sum(s%mesh%line_n_nodes(1:size(s%model%lines))) + sum(s%info%rod_nodes) + &
          s%n_points + 1 + s%n_bodies
   end function places

   !> The system of h when it can take external kinematics (initialised, WaveKin 1, in
   !> water); else null, with why on stderr.
   function ready(h, what) result(cs)
      type(c_ptr), intent(in) :: h          !< system
      character(len=*), intent(in) :: what  !< the function
      type(capi_system_t), pointer :: cs
      cs => system_of(h)
      if (.not. associated(cs)) return
      if (cs%s%stage /= 1 .or. .not. cs%s%info%external_waves .or. &
          .not. cs%s%prob%water%active) then
         write (error_unit, '(a)') 'rodyn: error: '//what//': the system takes external '// &
            'water kinematics once initialised, from a file with WaveKin 1, in water'
         cs => null()
      end if
   end function ready

   !> MoorDyn_ExternalWaveKinInit, MoorDyn_ExternalWaveKinGetN: the number of places.
   function md_wk_init(h, n) result(code) bind(c, name='MoorDyn_ExternalWaveKinInit')
      type(c_ptr), value :: h               !< system
      integer(c_int), intent(out) :: n      !< unsigned int: places
      integer(c_int) :: code
      code = md_wk_n(h, n)
   end function md_wk_init

   function md_wk_n(h, n) result(code) bind(c, name='MoorDyn_ExternalWaveKinGetN')
      type(c_ptr), value :: h               !< system
      integer(c_int), intent(out) :: n      !< unsigned int: places
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      code = md_invalid_value
      if (.not. associated(system_of(h))) return
      n = 0
      cs => ready(h, 'MoorDyn_ExternalWaveKinInit')
      if (.not. associated(cs)) return
      n = int(places(cs%s), c_int)
      code = md_success
   end function md_wk_n

   !> MoorDyn_ExternalWaveKinGetCoordinates: where the places are now [m] (3 a place).
   function md_wk_coords(h, r) result(code) &
      bind(c, name='MoorDyn_ExternalWaveKinGetCoordinates')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: r               !< double[3 n]
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      real(c_double), pointer :: rp(:, :)
      real(wp) :: rb(6), rd(6)
      integer :: l, k, j, q
      code = md_invalid_value
      if (.not. (associated(system_of(h)) .and. c_associated(r))) return
      cs => ready(h, 'MoorDyn_ExternalWaveKinGetCoordinates')
      if (.not. associated(cs)) return
      call c_f_pointer(r, rp, [3, places(cs%s)])
      j = 0
      associate (s => cs%s)
         do l = 1, size(s%model%lines)
            do k = 1, s%mesh%line_n_nodes(l)
               rp(:, j + k) = real(s%state%x(:, mesh_node(s%mesh, l, k)), c_double)
            end do
            j = j + s%mesh%line_n_nodes(l)
         end do
         do q = 1, size(s%info%rod_nodes)
            do k = 1, s%info%rod_nodes(q)
               rp(:, j + k) = real(s%info%rod_ends(1:3, q) + (s%info%rod_ends(4:6, q) - &
                  s%info%rod_ends(1:3, q))*real(k - 1, wp)/real(s%info%rod_nodes(q) - 1, wp), &
                  c_double)
            end do
            j = j + s%info%rod_nodes(q)
         end do
         do q = 1, s%n_points
            rp(:, j + q) = real(system_point_x(s, q), c_double)
         end do
         j = j + s%n_points + 1
         rp(:, j) = 0.0_c_double               ! the ground
         do q = 1, s%n_bodies
            call system_body_state(s, q, rb, rd)
            rp(:, j + q) = real(rb(1:3), c_double)
         end do
      end associate
      code = md_success
   end function md_wk_coords

   !> MoorDyn_ExternalWaveKinSet: the water's velocity U and acceleration Ud at the places
   !> (3 a place each; t, their time, as MoorDyn, not used), for the steps from now on.
   function md_wk_set(h, u, ud, t) result(code) bind(c, name='MoorDyn_ExternalWaveKinSet')
      type(c_ptr), value :: h               !< system
      type(c_ptr), value :: u, ud           !< const double[3 n]
      real(c_double), value :: t            !< time [s]
      integer(c_int) :: code
      type(capi_system_t), pointer :: cs
      real(c_double), pointer :: up(:, :), udp(:, :)
      real(wp), allocatable :: ext(:, :)
      integer :: l, k, j, q, node
      code = md_invalid_value
      if (.not. (associated(system_of(h)) .and. c_associated(u) .and. c_associated(ud))) &
         return
      cs => ready(h, 'MoorDyn_ExternalWaveKinSet')
      if (.not. associated(cs)) return
      call c_f_pointer(u, up, [3, places(cs%s)])
      call c_f_pointer(ud, udp, [3, places(cs%s)])
      associate (s => cs%s)
         allocate (ext(6, s%mesh%n_nodes))
         ext = 0.0_wp
         j = 0
         do l = 1, size(s%model%lines)
            do k = 1, s%mesh%line_n_nodes(l)
               node = mesh_node(s%mesh, l, k)
               ext(1:3, node) = real(up(:, j + k), wp)
               ext(4:6, node) = real(udp(:, j + k), wp)
            end do
            j = j + s%mesh%line_n_nodes(l)
         end do
         j = j + sum(s%info%rod_nodes)
         do q = 1, s%n_points                  ! a free point's own node
            node = s%mesh%point_node(q)
            if (node == 0) cycle
            ext(1:3, node) = real(up(:, j + q), wp)
            ext(4:6, node) = real(udp(:, j + q), wp)
         end do
         call water_set_external(s%prob%water, ext)
      end associate
      code = md_success
   end function md_wk_set

end module rodyn_capi_wavekin
