/*!
\ingroup PkgTetrahedralLatticeMeshingConcepts
\cgalConcept

A frame field gives, at every point \f$ x \f$ of a domain, a frame \f$ T(x) \f$: a 3x3
matrix whose three columns are the local lattice axes with their lengths (dissertation
2.1.2). The axes need be neither orthogonal (a frame field) nor of unit length; when
they are orthonormal everywhere the field is a cross field. \f$ B(x) = T(x)^{-1} \f$ maps
a vector at \f$ x \f$ into the "imagined" isotropic space, where a lattice aligned with the
field becomes the regular cubic lattice of unit spacing: for the edge vectors
\f$ e_1, e_2, e_3 \f$ of a hexahedron aligned with the field, \f$ B [e_1, e_2, e_3] = I \f$.

The columns of \f$ T \f$ are defined up to order and sign: the lattice meshers only use
the set \f$ \{\pm t_1, \pm t_2, \pm t_3\} \f$.

A model must never return a degenerate frame (a non-finite entry, a zero axis, or
coplanar axes, see `Frame_fields::is_degenerate_frame()`); where its formula or data
give one, it throws `std::invalid_argument` with a message saying where.

\cgalHasModel `CGAL::Frame_fields::Constant_frame_field_3<GeomTraits>`
\cgalHasModel `CGAL::Frame_fields::Closed_form_frame_field_3<GeomTraits, Function>`
\cgalHasModel `CGAL::Frame_fields::Discrete_frame_field_3<GeomTraits>`
*/
class FrameField_3
{
public:
  /// \name Types
  /// @{

  /// the point type, `Kernel::Point_3`
  typedef unspecified_type Point_3;

  /// `Eigen::Matrix3d`
  typedef unspecified_type Matrix;

  /// @}

  /// \name Operations
  /// @{

  /// the frame at `p`: its columns are the local lattice axes with their lengths
  Matrix T(const Point_3& p) const;

  /// \f$ T(p)^{-1} \f$, the map into the isotropic space at `p`
  Matrix B(const Point_3& p) const;

  /// @}
};
