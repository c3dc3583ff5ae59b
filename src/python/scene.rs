//! The scene as native objects: lights, materials and the light model, checked once when built
//! and handed to every call as they are. They pickle through their constructors (which check
//! them again) and compare equal by value.

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::exceptions::{PyIndexError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use super::arrays::shape_text;
use super::runtime::to_pyerr;
use crate::gl::light::Light;
use crate::gl::material::Material as GlMaterial;
use crate::gl::scene::{Scene as GlScene, Specular, ValidScene};

/// The widths a parameter's last axis may have: `&[]` for a number, 3 or 4 for colours (a
/// missing alpha is 1, every colour's default alpha).
type Widths = &'static [usize];

/// The parameters of a light, in the order of `glshade.Light`'s signature, with their widths.
const LIGHT_PARAMETERS: [(&str, Widths); 12] = [
    ("position", &[4]),
    ("diffuse", &[3, 4]),
    ("specular", &[3, 4]),
    ("constant_attenuation", &[]),
    ("linear_attenuation", &[]),
    ("quadratic_attenuation", &[]),
    ("spot_direction", &[3]),
    ("spot_exponent", &[]),
    ("spot_cutoff", &[]),
    ("ambient", &[3, 4]),
    ("spot_inner_cutoff", &[]),
    ("range", &[]),
];

/// The parameters of a material, in the order of `glshade.Material`'s signature.
const MATERIAL_PARAMETERS: [(&str, Widths); 5] = [
    ("ambient", &[3, 4]),
    ("diffuse", &[3, 4]),
    ("specular", &[3, 4]),
    ("emission", &[3, 4]),
    ("shininess", &[]),
];

/// The values of one parameter of a `T`, by name: a row of a colour or vector, or one number.
type Field<T> = for<'a> fn(&'a mut T, &str) -> &'a mut [f64];

/// The values of one light parameter, by name.
fn light_field<'a>(light: &'a mut Light, name: &str) -> &'a mut [f64] {
    match name {
        "position" => &mut light.position,
        "diffuse" => &mut light.diffuse,
        "specular" => &mut light.specular,
        "ambient" => &mut light.ambient,
        "spot_direction" => &mut light.spot_direction,
        "constant_attenuation" => std::slice::from_mut(&mut light.constant_attenuation),
        "linear_attenuation" => std::slice::from_mut(&mut light.linear_attenuation),
        "quadratic_attenuation" => std::slice::from_mut(&mut light.quadratic_attenuation),
        "spot_exponent" => std::slice::from_mut(&mut light.spot_exponent),
        "spot_cutoff" => std::slice::from_mut(&mut light.spot_cutoff),
        "spot_inner_cutoff" => std::slice::from_mut(&mut light.spot_inner_cutoff),
        "range" => std::slice::from_mut(&mut light.range),
        _ => unreachable!("not a light parameter: {name}"),
    }
}

/// The values of one material parameter, by name.
fn material_field<'a>(material: &'a mut GlMaterial, name: &str) -> &'a mut [f64] {
    match name {
        "ambient" => &mut material.ambient,
        "diffuse" => &mut material.diffuse,
        "specular" => &mut material.specular,
        "emission" => &mut material.emission,
        "shininess" => std::slice::from_mut(&mut material.shininess),
        _ => unreachable!("not a material parameter: {name}"),
    }
}

/// One parameter as given: one value for every light, or one row per light.
struct Given<'py> {
    name: &'static str,
    array: PyReadonlyArrayDyn<'py, f64>,
    /// The number of rows, when the parameter has one row per light.
    rows: Option<usize>,
}

impl<'py> Given<'py> {
    /// Checks `array`'s shape against `widths`: (w,) or (L, w) for a vector, () or (L,) for
    /// a number, where `per_row` allows the leading L.
    fn new(
        name: &'static str,
        widths: Widths,
        array: PyReadonlyArrayDyn<'py, f64>,
        per_row: bool,
    ) -> PyResult<Self> {
        let shape = array.shape().to_vec();
        let rank = usize::from(!widths.is_empty());
        let width_ok = widths.is_empty() || shape.last().is_some_and(|w| widths.contains(w));
        let rows = match shape.len().checked_sub(rank) {
            Some(0) if width_ok => None,
            Some(1) if width_ok && per_row => Some(shape[0]),
            _ => {
                let one = match widths {
                    [] => "a number".to_owned(),
                    _ => widths
                        .iter()
                        .map(|w| format!("({w},)"))
                        .collect::<Vec<_>>()
                        .join(" or "),
                };
                let per_light = match widths {
                    [] => " or shape (L,)".to_owned(),
                    _ => widths.iter().fold(String::new(), |text, w| {
                        text + " or (L, " + &w.to_string() + ")"
                    }),
                };
                let expected = if per_row { one + &per_light } else { one };
                return Err(PyValueError::new_err(format!(
                    "{name} must be {expected}, got shape {}",
                    shape_text(&shape)
                )));
            }
        };
        Ok(Self { name, array, rows })
    }

    /// Writes row `i` (or the shared value) into `field`.
    fn write(&self, i: usize, field: &mut [f64]) {
        let view = self.array.as_array();
        let row = match self.rows {
            Some(_) => view.index_axis(numpy::ndarray::Axis(0), i),
            None => view,
        };
        for (dst, src) in field.iter_mut().zip(row.iter()) {
            *dst = *src;
        }
    }
}

/// Reads the parameters `values` (in the order of `table`) into `count` items made from
/// `default`, through `field`.
fn build<T: Clone>(
    table: &[(&'static str, Widths)],
    values: Vec<PyReadonlyArrayDyn<'_, f64>>,
    per_row: bool,
    count: Option<usize>,
    default: &T,
    field: Field<T>,
) -> PyResult<Vec<T>> {
    if values.len() != table.len() {
        return Err(PyTypeError::new_err(format!(
            "expected {} parameters, got {}",
            table.len(),
            values.len()
        )));
    }
    let given = table
        .iter()
        .zip(values)
        .map(|(&(name, widths), array)| Given::new(name, widths, array, per_row))
        .collect::<PyResult<Vec<_>>>()?;
    let mut counts: Vec<(&str, usize)> = given
        .iter()
        .filter_map(|g| g.rows.map(|r| (g.name, r)))
        .collect();
    if let Some(c) = count {
        counts.push(("count", c));
    }
    let n = counts.first().map_or(1, |&(_, r)| r);
    if counts.iter().any(|&(_, r)| r != n) {
        let found: Vec<String> = counts.iter().map(|(k, r)| format!("{k}: {r}")).collect();
        return Err(PyValueError::new_err(format!(
            "per-light parameters must all have the same number of rows, got {}",
            found.join(", ")
        )));
    }
    let mut items = Vec::new();
    items.try_reserve_exact(n).map_err(|_| {
        pyo3::exceptions::PyMemoryError::new_err(format!("cannot allocate {n} lights"))
    })?;
    for i in 0..n {
        let mut item = default.clone();
        for g in &given {
            g.write(i, field(&mut item, g.name));
        }
        items.push(item);
    }
    Ok(items)
}

/// The parameter `name` of `table` (a `what` parameter) of every item as a read-only array of
/// shape `leading` + (w,) for a vector, `leading` for a number.
fn values<'py, T: Clone + Default>(
    py: Python<'py>,
    (table, what): (&[(&'static str, Widths)], &str),
    items: &[T],
    name: &str,
    field: Field<T>,
    leading: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    let widths = table
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, w)| *w)
        .ok_or_else(|| PyValueError::new_err(format!("not a {what} parameter: {name:?}")))?;
    let mut flat = Vec::new();
    for item in items {
        flat.extend_from_slice(field(&mut item.clone(), name));
    }
    let mut shape = leading.to_vec();
    if !widths.is_empty() {
        shape.push(field(&mut T::default(), name).len());
    }
    let array = PyArray1::from_vec(py, flat).reshape(shape)?.into_any();
    array.call_method1("setflags", (false,))?;
    Ok(array)
}

/// GL's default of each parameter of `table`, read from `default`, as a dict for the
/// signatures of the package's classes.
fn defaults<'py, T: Clone>(
    py: Python<'py>,
    table: &[(&'static str, Widths)],
    default: &T,
    field: Field<T>,
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for &(name, widths) in table {
        let mut item = default.clone();
        let values = field(&mut item, name).to_vec();
        if widths.is_empty() {
            dict.set_item(name, values[0])?;
        } else {
            dict.set_item(name, PyTuple::new(py, values)?)?;
        }
    }
    Ok(dict)
}

/// Any number of GL lights (`GL_LIGHTi` state), checked; see `glshade.Lights`.
#[pyclass(frozen, eq, module = "glshade._glshade")]
#[derive(Clone, PartialEq)]
pub struct Lights {
    pub(crate) lights: Vec<Light>,
}

#[pymethods]
impl Lights {
    /// The lights of `parameters` (float64 arrays in the order of `PARAMETERS`, each one value
    /// for all lights or one row per light) and `count` (the number of lights when no parameter
    /// has rows; default 1). Raises `ValueError` naming a bad parameter and its light.
    #[new]
    #[pyo3(signature = (parameters, count=None))]
    fn new(parameters: Vec<PyReadonlyArrayDyn<'_, f64>>, count: Option<usize>) -> PyResult<Self> {
        let lights = build(
            &LIGHT_PARAMETERS,
            parameters,
            true,
            count,
            &Light::default(),
            light_field,
        )?;
        for (i, light) in lights.iter().enumerate() {
            light.validate(i).map_err(to_pyerr)?;
        }
        Ok(Self { lights })
    }

    /// The parameter names, in the order the constructor takes them.
    #[classattr]
    #[allow(non_snake_case)]
    fn PARAMETERS() -> Vec<&'static str> {
        LIGHT_PARAMETERS.iter().map(|(n, _)| *n).collect()
    }

    /// GL's default of each parameter (`GL_LIGHT0`'s, for every light).
    #[classattr]
    #[allow(non_snake_case)]
    fn DEFAULTS(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        defaults(py, &LIGHT_PARAMETERS, &Light::default(), light_field)
    }

    fn __len__(&self) -> usize {
        self.lights.len()
    }

    /// One parameter of every light: (L, w) float64, or (L,) for a number; read-only.
    fn column<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let leading = [self.lights.len()];
        let table = (&LIGHT_PARAMETERS[..], "light");
        values(py, table, &self.lights, name, light_field, &leading)
    }

    /// The lights at `indices` (int64, each in [0, L)), in that order.
    fn take(&self, indices: Vec<i64>) -> PyResult<Self> {
        let n = self.lights.len();
        let lights = indices
            .iter()
            .map(|&i| {
                usize::try_from(i)
                    .ok()
                    .and_then(|i| self.lights.get(i).copied())
                    .ok_or_else(|| {
                        PyIndexError::new_err(format!(
                            "light index {i} is out of range for {n} lights"
                        ))
                    })
            })
            .collect::<PyResult<_>>()?;
        Ok(Self { lights })
    }

    /// All lights of `parts`, in order.
    #[staticmethod]
    fn concatenate(parts: Vec<PyRef<'_, Lights>>) -> Self {
        Self {
            lights: parts
                .iter()
                .flat_map(|p| p.lights.iter().copied())
                .collect(),
        }
    }

    fn __getnewargs__<'py>(&self, py: Python<'py>) -> PyResult<(Vec<Bound<'py, PyAny>>, usize)> {
        let columns = LIGHT_PARAMETERS
            .iter()
            .map(|(name, _)| self.column(py, name))
            .collect::<PyResult<_>>()?;
        Ok((columns, self.lights.len()))
    }
}

/// The material of one face, checked; see `glshade.Material`.
#[pyclass(frozen, eq, module = "glshade._glshade")]
#[derive(Clone, PartialEq)]
pub struct Material {
    pub(crate) material: GlMaterial,
}

#[pymethods]
impl Material {
    /// The material of `parameters` (float64 arrays in the order of `PARAMETERS`). Raises
    /// `ValueError` naming a bad parameter.
    #[new]
    fn new(parameters: Vec<PyReadonlyArrayDyn<'_, f64>>) -> PyResult<Self> {
        let material = build(
            &MATERIAL_PARAMETERS,
            parameters,
            false,
            None,
            &GlMaterial::default(),
            material_field,
        )?
        .remove(0);
        material.validate("material").map_err(to_pyerr)?;
        Ok(Self { material })
    }

    /// The parameter names, in the order the constructor takes them.
    #[classattr]
    #[allow(non_snake_case)]
    fn PARAMETERS() -> Vec<&'static str> {
        MATERIAL_PARAMETERS.iter().map(|(n, _)| *n).collect()
    }

    /// GL's initial material.
    #[classattr]
    #[allow(non_snake_case)]
    fn DEFAULTS(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        defaults(
            py,
            &MATERIAL_PARAMETERS,
            &GlMaterial::default(),
            material_field,
        )
    }

    /// One parameter as a read-only float64 array: (4,), or () for `shininess`.
    fn get<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let table = (&MATERIAL_PARAMETERS[..], "material");
        values(py, table, &[self.material], name, material_field, &[])
    }

    fn __getnewargs__<'py>(&self, py: Python<'py>) -> PyResult<(Vec<Bound<'py, PyAny>>,)> {
        let values = MATERIAL_PARAMETERS
            .iter()
            .map(|(name, _)| self.get(py, name))
            .collect::<PyResult<_>>()?;
        Ok((values,))
    }
}

/// A scene's constructor arguments for pickle: the positional ones and the keywords.
type NewArgs<'py> = ((Py<Lights>, Py<Material>), Bound<'py, PyDict>);

/// Lights, materials and the light model, checked; see `glshade.Scene`.
#[pyclass(frozen, module = "glshade._glshade")]
pub struct Scene {
    pub(crate) state: ValidScene,
    lights: Py<Lights>,
    material: Py<Material>,
    back_material: Option<Py<Material>>,
}

#[pymethods]
impl Scene {
    /// The scene of these lights, materials (`back_material` None: the front one) and light
    /// model values. Raises `ValueError` naming a bad value.
    #[new]
    #[pyo3(signature = (
        lights, material, *, back_material, global_ambient, viewer, two_side, separate_specular,
        specular, specular_gate
    ))]
    fn new(
        lights: Bound<'_, Lights>,
        material: Bound<'_, Material>,
        back_material: Option<Bound<'_, Material>>,
        global_ambient: [f64; 4],
        viewer: [f64; 4],
        two_side: bool,
        separate_specular: bool,
        specular: &str,
        specular_gate: bool,
    ) -> PyResult<Self> {
        let front = material.get().material;
        let scene = GlScene {
            lights: lights.get().lights.clone(),
            material: front,
            back_material: back_material.as_ref().map_or(front, |m| m.get().material),
            global_ambient,
            viewer,
            two_side,
            separate_specular,
            specular: Specular::parse(specular).map_err(to_pyerr)?,
            specular_gate,
        };
        let scene = scene.validated().map_err(to_pyerr)?;
        Ok(Self {
            state: scene,
            lights: lights.unbind(),
            material: material.unbind(),
            back_material: back_material.map(Bound::unbind),
        })
    }

    /// GL's initial light model: `global_ambient`, `viewer`, `two_side`, `separate_specular`,
    /// `specular` and `specular_gate`.
    #[classattr]
    #[allow(non_snake_case)]
    fn DEFAULTS(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        light_model(py, &GlScene::default())
    }

    /// The names of the colours `shade` returns, in output order.
    #[getter]
    fn outputs(&self) -> Vec<&'static str> {
        self.state.output_names().to_vec()
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<Scene>()
            .is_ok_and(|o| o.get().state == self.state)
    }

    /// The lights, as one `Lights`.
    #[getter]
    fn lights(&self, py: Python<'_>) -> Py<Lights> {
        self.lights.clone_ref(py)
    }

    /// The front material.
    #[getter]
    fn material(&self, py: Python<'_>) -> Py<Material> {
        self.material.clone_ref(py)
    }

    /// The back material as given, or None (the front one).
    #[getter]
    fn back_material(&self, py: Python<'_>) -> Option<Py<Material>> {
        self.back_material.as_ref().map(|m| m.clone_ref(py))
    }

    /// `GL_LIGHT_MODEL_AMBIENT`, RGBA, a tuple as in `DEFAULTS`.
    #[getter]
    fn global_ambient<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.state.global_ambient)
    }

    /// The homogeneous viewer position in eye coordinates, a tuple as in `DEFAULTS`.
    #[getter]
    fn viewer<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.state.viewer)
    }

    /// `GL_LIGHT_MODEL_TWO_SIDE`.
    #[getter]
    fn two_side(&self) -> bool {
        self.state.two_side
    }

    /// `GL_SEPARATE_SPECULAR_COLOR`.
    #[getter]
    fn separate_specular(&self) -> bool {
        self.state.separate_specular
    }

    /// The specular model: `"blinn"` or `"phong"`.
    #[getter]
    fn specular(&self) -> &'static str {
        specular_name(self.state.specular)
    }

    /// GL's f_i: no specular from a light unless n·VP > 0 (`False`: learnopengl's shaders).
    #[getter]
    fn specular_gate(&self) -> bool {
        self.state.specular_gate
    }

    /// Pickling: the constructor's arguments, positional and keyword.
    fn __getnewargs_ex__<'py>(&self, py: Python<'py>) -> PyResult<NewArgs<'py>> {
        let keywords = light_model(py, &self.state)?;
        keywords.set_item("back_material", self.back_material(py))?;
        Ok(((self.lights(py), self.material(py)), keywords))
    }
}

/// The light model of `s` as the keywords of `Scene`: `global_ambient`, `viewer`, `two_side`,
/// `separate_specular`, `specular` and `specular_gate`.
fn light_model<'py>(py: Python<'py>, s: &GlScene) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    dict.set_item("global_ambient", PyTuple::new(py, s.global_ambient)?)?;
    dict.set_item("viewer", PyTuple::new(py, s.viewer)?)?;
    dict.set_item("two_side", s.two_side)?;
    dict.set_item("separate_specular", s.separate_specular)?;
    dict.set_item("specular", specular_name(s.specular))?;
    dict.set_item("specular_gate", s.specular_gate)?;
    Ok(dict)
}

fn specular_name(specular: Specular) -> &'static str {
    match specular {
        Specular::Blinn => "blinn",
        Specular::Phong => "phong",
    }
}
