#include "tests/support/ar_fixture.hpp"

#include "convert/hatt_model_reader.hpp"

namespace haptex::test {

// Four AR(5) models on the corners of [0, 100] mm/s x [0, 2] N, two triangles. Model 2's LSFs
// nearly pair up (a pole at radius 0.99972), model 4's too (0.99657), and blending the
// coefficients (not the LSFs) of models 3 and 4 would be unstable: a hard case for blending.
// ARcoeff from numpy's lsf2poly (tests/golden/ar_golden.py).
const char* const kArFixtureXml = R"(<?xml version="1.0" encoding="utf-8"?>
<modelSet texture="901">
   <material>Fixture</material>
   <AccelUnits>m/s^2</AccelUnits>
   <SpeedUnits>mm/s</SpeedUnits>
   <ForceUnits>N</ForceUnits>
   <SampleRate>10000</SampleRate>
   <mu>0.3</mu>
   <numMod>4</numMod>
   <numTri>2</numTri>
   <maxSpeed>100</maxSpeed>
   <maxForce>2</maxForce>
   <speedList type="array"><value>0</value><value>100</value><value>0</value><value>100</value></speedList>
   <forceList type="array"><value>0</value><value>0</value><value>2</value><value>2</value></forceList>
   <tri type="array"><value>1</value><value>2</value><value>4</value></tri>
   <tri type="array"><value>1</value><value>4</value><value>3</value></tri>
   <numARCoeff>5</numARCoeff>
   <numMACoeff>0</numMACoeff>
   <model><modNum>1</modNum>
      <ARcoeff><value>1</value><value>-1.153931481387</value><value>-0.150080396764</value><value>0.370186765366</value><value>0.014340218049</value><value>0.000383589591</value></ARcoeff>
      <ARlsf><value>0.20</value><value>0.45</value><value>1.10</value><value>1.90</value><value>2.60</value></ARlsf>
      <MAcoeff><value>1</value></MAcoeff><MAlsf/>
      <var>0</var><speedMod>0</speedMod><forceMod>0</forceMod></model>
   <model><modNum>2</modNum>
      <ARcoeff><value>1</value><value>-1.119327336658</value><value>0.105538801475</value><value>0.141646168386</value><value>-1.097193671628</value><value>0.978622713079</value></ARcoeff>
      <ARlsf><value>0.05</value><value>0.06</value><value>1.50</value><value>1.52</value><value>3.10</value></ARlsf>
      <MAcoeff><value>1</value></MAcoeff><MAlsf/>
      <var>0</var><speedMod>100</speedMod><forceMod>0</forceMod></model>
   <model><modNum>3</modNum>
      <ARcoeff><value>1</value><value>2.342049474447</value><value>2.049020059185</value><value>0.615885214352</value><value>-0.290645028465</value><value>-0.235841706251</value></ARcoeff>
      <ARlsf><value>0.95</value><value>1.94</value><value>2.28</value><value>2.76</value><value>2.96</value></ARlsf>
      <MAcoeff><value>1</value></MAcoeff><MAlsf/>
      <var>0</var><speedMod>0</speedMod><forceMod>2</forceMod></model>
   <model><modNum>4</modNum>
      <ARcoeff><value>1</value><value>-1.076287714536</value><value>-0.935032147708</value><value>0.468732906409</value><value>1.246497052588</value><value>-0.692957673922</value></ARcoeff>
      <ARlsf><value>0.10</value><value>0.12</value><value>0.80</value><value>2.50</value><value>2.51</value></ARlsf>
      <MAcoeff><value>1</value></MAcoeff><MAlsf/>
      <var>0.5</var><speedMod>100</speedMod><forceMod>2</forceMod></model>
</modelSet>
)";

ar::PiecewiseArModel ar_fixture() { return ar::PiecewiseArModel(convert::parse_hatt_model(kArFixtureXml, "fixture.xml")); }

}  // namespace haptex::test
