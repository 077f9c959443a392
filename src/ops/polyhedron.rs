//! Closed polyhedral shells (docs/FORMAT.md `polyhedron`; OPERATIONS.md §4): vertices and
//! planar faces given as index lists, counter-clockwise seen from outside.
//!
//! Validation is exact (every double is an exact rational): each face has at least
//! three distinct indices in range, its vertices are coplanar and not all collinear;
//! the shell is closed and consistently oriented (every directed edge appears once and
//! its reverse once); and it is oriented outward (positive signed volume). Each failure
//! is a typed error naming `faces[i]` or `vertices[i]`.

use rug::Rational;
use std::collections::BTreeMap;

use crate::error::GeomError;
use crate::num::ring::{cross3, dot3, sub3, Field, Ring, V3};

/// A validated closed shell with planar faces, in exact rationals.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyhedron {
    vertices: Vec<V3<Rational>>,
    faces: Vec<Face>,
}

/// A planar face: its vertex indices (counter-clockwise seen from outside), its exact
/// outward normal `n` (Newell's sum, `|n|` = twice the area) and offset `n·v₀`.
#[derive(Debug, Clone, PartialEq)]
pub struct Face {
    pub indices: Vec<usize>,
    pub normal: V3<Rational>,
    pub offset: Rational,
    /// The coordinate dropped when the face is projected to 2D (`normal[axis] ≠ 0`).
    pub axis: usize,
}

fn invalid(field: String, reason: impl Into<String>) -> GeomError {
    GeomError::InvalidValue {
        field,
        reason: reason.into(),
    }
}

impl Polyhedron {
    /// Validate a shell (see the module documentation for every check).
    pub fn new(vertices: Vec<V3<Rational>>, faces: Vec<Vec<usize>>) -> Result<Self, GeomError> {
        if vertices.len() < 4 {
            return Err(invalid(
                "vertices".into(),
                format!(
                    "a closed shell needs at least 4 vertices, found {}",
                    vertices.len()
                ),
            ));
        }
        if faces.len() < 4 {
            return Err(invalid(
                "faces".into(),
                format!(
                    "a closed shell needs at least 4 faces, found {}",
                    faces.len()
                ),
            ));
        }
        let faces = faces
            .into_iter()
            .enumerate()
            .map(|(i, f)| face(&vertices, f).map_err(|e| e.at(&format!("faces[{i}]"))))
            .collect::<Result<Vec<_>, _>>()?;
        check_closed(&faces)?;
        let p = Polyhedron { vertices, faces };
        if p.signed_volume6().sign().is_le() {
            return Err(invalid(
                "faces".into(),
                "the faces are oriented inward (they must be counter-clockwise seen from \
                 outside) or the shell encloses no volume",
            ));
        }
        Ok(p)
    }

    pub fn vertices(&self) -> &[V3<Rational>] {
        &self.vertices
    }
    pub fn faces(&self) -> &[Face] {
        &self.faces
    }
    /// The vertices of face `f`, in order.
    pub fn face_vertices<'a>(&'a self, f: &'a Face) -> impl Iterator<Item = &'a V3<Rational>> + 'a {
        f.indices.iter().map(move |&i| &self.vertices[i])
    }

    /// Six times the signed volume: Σ over faces of Σ over fan triangles det(v₀, vᵢ, vᵢ₊₁).
    fn signed_volume6(&self) -> Rational {
        let mut total = Rational::new();
        for f in &self.faces {
            let v0 = &self.vertices[f.indices[0]];
            for w in f.indices[1..].windows(2) {
                let (a, b) = (&self.vertices[w[0]], &self.vertices[w[1]]);
                total += dot3(v0, &cross3(a, b));
            }
        }
        total
    }
}

/// Newell's normal `Σ vᵢ × vᵢ₊₁`: for a planar polygon, twice its vector area.
fn newell(vs: &[&V3<Rational>]) -> V3<Rational> {
    let mut n = [Rational::new(), Rational::new(), Rational::new()];
    for i in 0..vs.len() {
        let c = cross3(vs[i], vs[(i + 1) % vs.len()]);
        for k in 0..3 {
            n[k] += &c[k];
        }
    }
    n
}

fn face(vertices: &[V3<Rational>], indices: Vec<usize>) -> Result<Face, GeomError> {
    if indices.len() < 3 {
        return Err(invalid(String::new(), "a face needs at least 3 vertices"));
    }
    for (k, &i) in indices.iter().enumerate() {
        if i >= vertices.len() {
            return Err(invalid(
                format!("[{k}]"),
                format!(
                    "vertex index {i} out of range (there are {})",
                    vertices.len()
                ),
            ));
        }
        if indices[..k].contains(&i) {
            return Err(invalid(
                format!("[{k}]"),
                format!("vertex {i} repeats in the face"),
            ));
        }
    }
    let vs: Vec<&V3<Rational>> = indices.iter().map(|&i| &vertices[i]).collect();
    // Not all collinear: some triple spans a plane.
    let v0 = vs[0];
    let spans = vs[1..]
        .iter()
        .flat_map(|a| vs[1..].iter().map(move |b| (a, b)))
        .any(|(a, b)| {
            !cross3(&sub3(a, v0), &sub3(b, v0))
                .iter()
                .all(Field::is_zero)
        });
    if !spans {
        return Err(invalid(String::new(), "the face's vertices are collinear"));
    }
    let normal = newell(&vs);
    let offset = dot3(&normal, v0);
    for (k, v) in vs.iter().enumerate() {
        if dot3(&normal, v) != offset {
            return Err(invalid(
                format!("[{k}]"),
                "the face is not planar (this vertex is off the plane of the others)",
            ));
        }
    }
    if normal.iter().all(Field::is_zero) {
        return Err(invalid(String::new(), "the face has zero area"));
    }
    let axis = (0..3)
        .max_by(|&i, &j| normal[i].clone().abs().cmp(&normal[j].clone().abs()))
        .unwrap_or(2);
    Ok(Face {
        indices,
        normal,
        offset,
        axis,
    })
}

/// Every directed edge once, and its reverse once.
fn check_closed(faces: &[Face]) -> Result<(), GeomError> {
    let mut edges: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for (fi, f) in faces.iter().enumerate() {
        let n = f.indices.len();
        for k in 0..n {
            let e = (f.indices[k], f.indices[(k + 1) % n]);
            if let Some(other) = edges.insert(e, fi) {
                return Err(invalid(
                    format!("faces[{fi}]"),
                    format!(
                        "edge {} → {} also appears in this direction in faces[{other}]: \
                         the orientation is inconsistent or the shell is not manifold",
                        e.0, e.1
                    ),
                ));
            }
        }
    }
    for (&(a, b), &fi) in &edges {
        if !edges.contains_key(&(b, a)) {
            return Err(invalid(
                format!("faces[{fi}]"),
                format!("edge {a} → {b} has no neighbour face: the shell is not closed"),
            ));
        }
    }
    Ok(())
}

/// Exact vector helpers used by the classifier (rationals only).
pub(crate) fn scale_add(p: &V3<Rational>, s: &Rational, r: &V3<Rational>) -> V3<Rational> {
    [
        p[0].plus(&s.times(&r[0])),
        p[1].plus(&s.times(&r[1])),
        p[2].plus(&s.times(&r[2])),
    ]
}
