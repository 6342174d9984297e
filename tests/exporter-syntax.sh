#!/bin/sh
# What exporters write that POV-Ray 3.7's parser takes (issue 42), in TAP.
# Scenes written here in the style of each exporter's output -- LDCad's
# declared model named on its own line; Blender's `diffuse 0.8 0` and
# finish subsurface; POV-Ray 3.0's max_trace_level outside global_settings;
# L3P's declarations in a scene without #version, which POV-Ray 3.7 takes
# for a 3.6 one; vertex-colour exports' three texture indices per face;
# LeoCAD's parts with LGEO-like fading transparent materials; Blender's
# caustics and photons blocks; three different textures per vertex --
# are rendered by hstrace and by the installed POV-Ray (+Q9, and +Q3/+Q4
# for the shadow masks) and compared by `hstrace compare` against the
# limits measured for each (the table below; issue 42's bar is an RMSE of
# at most 0.002 and no shadow-mask disagreement in the interior). Then the
# mistakes near those forms (status 2 at FILE:LINE:COLUMN, no image) and
# what they approximate (reported, refused by --strict).
#
# Environment: top_srcdir, top_builddir (default .), POVRAY (path or name of
# povray; may be empty).
set -u
srcdir=${top_srcdir:-.}
builddir=${top_builddir:-.}
hstrace="$builddir/hstrace"
# shellcheck source=tests/tap.sh
. "$srcdir/tests/tap.sh"
tap_work hstsyntax
[ -x "$hstrace" ] || bail "$hstrace is not built"
run() { # runs hstrace, keeps stderr in $work/err and the status in $status
    "$hstrace" "$@" >"$work/out" 2>"$work/err"; status=$?
}

# --- LDCad: the model, a declared union, named on its own line -------------
# POV-Ray 3.7's Parse_Object takes a declared object (or light) identifier
# as a copy of it wherever it takes an object: at the top level
# (Parse_Frame), where LDCad names its model and we a light, and among a
# union's children (Parse_CSG; not as the first, which Parse_Object_Id reads
# as `object { ID ... }`), where the tile stands.
cat >"$work/ldcad.pov" <<'POV'
#version 3.7;
#declare assumedGamma=1;
#declare doSeams=true;
#declare seamSize=0.3;
#declare doFloor=true;
global_settings { assumed_gamma assumedGamma ambient_light srgb <1,1,1> max_trace_level 8 }
background { color srgb 0.4 }

#declare ldColorCount=3;
#declare ldColor=array[ldColorCount][5] {
 {4,0.788235,0.101961,0.035294,1},
 {1,0,0.333333,0.74902,1},
 {14,0.94902,0.803922,0.215686,1}
}
#macro getColorIndex(ldCode)
 #local result=-1;
 #local i=0;
 #while (result=-1 & i<ldColorCount)
  #if (ldColor[i][0]=ldCode) #local result=i; #else #local i=i+1; #end
 #end
 result
#end
#local ldrawPlasticFin=finish { diffuse 1 brilliance 1 conserve_energy specular albedo 0.1 roughness 0.01 reflection 0.05 };
#macro ldrawPigment(colIdx)
 #local result=pigment { srgb <ldColor[colIdx][1], ldColor[colIdx][2], ldColor[colIdx][3]> };
 result
#end
#macro ldrawMatPlastic(ldCode)
 texture { pigment { ldrawPigment(getColorIndex(ldCode)) } finish { ldrawPlasticFin } }
#end
#declare ldMat4=material { ldrawMatPlastic(4) }
#declare ldMat1=material { ldrawMatPlastic(1) }
#declare ldMat14=material { ldrawMatPlastic(14) }

#macro sfSeam(sfMin, sfMax)
 #local s=sfMax-sfMin;
 #local c=sfMin+0.5*s;
 #local ss=<
  #if (s.x<=seamSize) 0.0 #else seamSize #end,
  #if (s.y<=seamSize) 0.0 #else seamSize #end,
  #if (s.z<=seamSize) 0.0 #else seamSize #end
 >;
 translate -c
 scale (s-ss)/s
 translate c
#end

// a 2x2 brick without studs: its box as a mesh2
#declare sf_brick=mesh2 {
 vertex_vectors { 8,
  <-20,0,-20>, <20,0,-20>, <20,0,20>, <-20,0,20>,
  <-20,-24,-20>, <20,-24,-20>, <20,-24,20>, <-20,-24,20> }
 face_indices { 12,
  <0,1,2>, <0,2,3>, <4,5,6>, <4,6,7>, <0,1,5>, <0,5,4>,
  <1,2,6>, <1,6,5>, <2,3,7>, <2,7,6>, <3,0,4>, <3,4,7> }
 #if (doSeams) sfSeam(<-20,-24,-20>, <20,0,20>) #end
}

// a tile, declared with its material, placed by name in the model
#declare sf_tile=object { sf_brick scale <0.5,0.3,0.5> translate <-40,0,-45> material {ldMat14} }

#declare sf_model=union {
 object { sf_brick matrix <1,0,0,0,1,0,0,0,1,-30,0,0> material {ldMat4} }
 object { sf_brick matrix <1,0,0,0,1,0,0,0,1,20,0,10> material {ldMat1} }
 object { sf_brick matrix <0.866,0,0.5,0,1,0,-0.5,0,0.866,-5,-24,0> material {ldMat14} }
 sf_tile
}

//=====Model root
sf_model

//=====Floor
#if (doFloor)
 plane { -y, 0 pigment { srgb 0.8 } finish { ambient 0.2 diffuse 0.7 } }
#end

//=====Lights
#declare ldLight=light_source { <-100,-300,-200> color srgb 0.8 }
ldLight
light_source { <200,-250,-100> color srgb 0.5 }

//=====Camera
camera {
 perspective
 angle 60
 location <60,-120,-160>
 right -image_width/image_height*x
 up y
 sky <0,-1,0>
 look_at <0,-14,0>
}
POV

# --- Blender's exporter: its finishes and meshes --------------------------
# `diffuse 0.8 0`: POV-Ray 3.7's Parse_Finish reads `diffuse [albedo]
# Amount [,] [Backside]` with an optional comma (Parse_Comma) and the
# backside wherever an expression starts (Allow_Float, default 0), so the
# second number is the backside's, 0: no light from behind. A finish's
# `subsurface { translucency C }` counts only where global_settings turns
# subsurface light transport on (trace.cpp), which this scene does not.
# Also as the exporter writes them: `texture { uv_mapping pigment {...} }`,
# texture_list without commas, three equal texture indices per face (POV-Ray
# blends a face's three textures by weight, which for one texture differs
# from it by its rounding: most of the RMSE below), an empty pattern
# declared with a function of it, the camera placed by rotate and
# translate, a light by a matrix.
cat >"$work/blender.pov" <<'POV'
//----------------------------------------------
//--In the style of Blender's POV-Ray exporter--
//----------------------------------------------
#version 3.7;

//--Global settings--
global_settings {
    assumed_gamma 1.0
    max_trace_level 5
    ambient_light rgb<0.2, 0.2, 0.2>
}

//--Patterns Definitions--
#declare PAT_Tex =
pigment {
}
#declare fPAT_Tex=
function{pigment{PAT_Tex}}

//--Background--
background {rgbt<0.05, 0.06, 0.08, 0>}

//--Cameras--
#declare camLocation  = <7.48, 5.34, 6.51>;
#declare camLookAt = <-27.1, 46.69, -0.9>;
camera {
    location  <0, 0, 0>
    look_at  <0, 0, -1>
    right <-1.3333333333333333, 0, 0>
    up <0, 1, 0>
    angle  49.134343
    rotate  <-27.1, 46.69, -0.9>
    translate <7.48, 5.34, 6.51>
}

//--Lamps--
light_source {
    < 0,0,0 >
    color rgb<1.6, 1.6, 1.6>
    fade_distance 15.0
    fade_power 2
    matrix <-0.290865, -0.055189, -0.955171,  -0.771101, 0.604525, 0.199883,  0.566393, 0.794672, -0.218391,  4.076245, 5.903862, -1.005454>
}
#declare lampTarget1= vrotate(<-4.076,-1.005,-5.904>,<0.6503,0.05522,1.866>);

//--Material Definitions--
#default{ pigment{ color srgb 0.8 }}
#declare shader_ = finish {  //translation of spec and mir levels for when no map influences them
    diffuse 0.8
    phong 70.0
}
#declare shader_Material = finish {  //translation of spec and mir levels for when no map influences them
    brilliance 1.8
    phong 0.5
    phong_size 25.2
    diffuse 0.8 0
    ambient 0.5
    emission 0
    conserve_energy
}
#declare shader_Skin = finish {
    specular 0.25
    roughness 0.05
    diffuse 0.7, 0
    ambient 0.3
    emission 0
    subsurface { translucency <0.8, 0.3, 0.2> }
}

//--Mesh objects--
#declare DATACube =
mesh2 {
    vertex_vectors {
        8,
        <1.000000, 1.000000, -1.000000>,
        <1.000000, -1.000000, -1.000000>,
        <-1.000000, -1.000000, -1.000000>,
        <-1.000000, 1.000000, -1.000000>,
        <1.000000, 0.999999, 1.000000>,
        <0.999999, -1.000001, 1.000000>,
        <-1.000000, -1.000000, 1.000000>,
        <-1.000000, 1.000000, 1.000000>
    }
    normal_vectors {
        6,
        <0.000000, 0.000000, -1.000000>,
        <-0.000000, -1.000000, -0.000000>,
        <1.000000, -0.000000, 0.000000>,
        <-1.000000, 0.000000, -0.000000>,
        <0.000000, 1.000000, 0.000000>,
        <0.000000, -0.000000, 1.000000>
    }
    uv_vectors {
        4,
        <0, 0>, <1, 0>, <1, 1>, <0, 1>
    }
    texture_list {
        2
        texture {
            pigment {rgbft<0.8, 0.2, 0.15, 0, 0>}
            finish {shader_Material}
        }
        texture {
            uv_mapping pigment { checker rgb <0.9, 0.9, 0.2> rgb <0.1, 0.3, 0.8> scale 0.25 }
            finish {shader_Skin}
        }
    }
    face_indices {
        12,
        <0,1,2>, 0,0,0,
        <0,2,3>, 0,0,0,
        <4,7,6>, 1,1,1,
        <4,6,5>, 1,1,1,
        <0,4,5>, 1,1,1,
        <0,5,1>, 1,1,1,
        <1,5,6>, 0,0,0,
        <1,6,2>, 0,0,0,
        <2,6,7>, 0,0,0,
        <2,7,3>, 0,0,0,
        <4,0,3>, 1,1,1,
        <4,3,7>, 1,1,1
    }
    normal_indices {
        12,
        <0,0,0>, <0,0,0>, <5,5,5>, <5,5,5>, <2,2,2>, <2,2,2>,
        <1,1,1>, <1,1,1>, <3,3,3>, <3,3,3>, <4,4,4>, <4,4,4>
    }
    uv_indices {
        12,
        <0,1,2>, <0,2,3>, <0,1,2>, <0,2,3>, <0,1,2>, <0,2,3>,
        <0,1,2>, <0,2,3>, <0,1,2>, <0,2,3>, <0,1,2>, <0,2,3>
    }
    interior {
        ior 1.000000
    }
    photons{    }
    radiosity {
        importance   1
    }
}
//----Blender Object Name:OBCube----
object {
    DATACube
    matrix <1.000000, 0.000000, 0.000000,  0.000000, -0.000000, -1.000000,  0.000000, 1.000000, -0.000000,  0.000000, 0.000000, 0.000000>
}
//----Blender Object Name:OBPlane----
#declare DATAPlane =
mesh2 {
    vertex_vectors { 4, <-6,-6,0>, <6,-6,0>, <6,6,0>, <-6,6,0> }
    texture_list { 1 texture { pigment {rgbft<0.7, 0.7, 0.7, 0, 0>} finish {shader_} } }
    face_indices { 2, <0,1,2>, 0,0,0, <0,2,3>, 0,0,0 }
}
object {
    DATAPlane
    matrix <1,0,0, 0,0,-1, 0,1,0, 0,-1.01,0>
}
POV

# --- POV-Ray 3.0's places for global settings ------------------------------
cat >"$work/toplevel.pov" <<'POV'
// Settings where POV-Ray 3.0 scenes wrote them, outside global_settings:
// POV-Ray 3.7's Parse_Frame still reads max_trace_level there (the
// mirrors show how deep), and max_intersections, which no longer matters.
#version 3.7;
global_settings { assumed_gamma 1 }
max_trace_level 2
max_intersections 64
camera { location <0.3, 1, -3> look_at <0, 1, 0> }
light_source { <2, 4, -3> color rgb 1 }
#declare Mirror = finish { ambient 0.05 diffuse 0.3 reflection 0.8 }
polygon { 4, <-2,0,1>, <2,0,1>, <2,2,1>, <-2,2,1> pigment { rgb <0.9, 0.9, 1> } finish { Mirror } }
polygon { 4, <-2,0,-4>, <2,0,-4>, <2,2,-4>, <-2,2,-4> pigment { rgb <1, 0.9, 0.8> } finish { Mirror } }
plane { y, 0 pigment { checker rgb <0.8, 0.2, 0.1> rgb 0.9 scale 0.5 } }
triangle { <-0.5,0.2,0>, <0.5,0.2,0>, <0,1.2,0> pigment { rgb <0.2, 0.7, 0.3> } }
POV

# --- L3P: declarations guarded by #ifndef, materials by macros, no #version
# POV-Ray 3.7 takes a scene without #version for a 3.6 one wherever it
# keeps 3.6's rules (EffectiveLanguageVersion: 3.62): here the transparent
# brick's own light, 1 - (filter * max(r, g, b) + transmit) (trace.cpp).
cat >"$work/l3p.pov" <<'POV'
// In the style of L3P's POV-Ray export: no #version (POV-Ray 3.7 reads it
// as a 3.6 scene), quality switches, finishes and colours declared only
// where not yet declared, materials by macros, parts as unions of meshes
// placed by two matrices each, the model a declared union.
#if (version < 3.1)
	#error "This POV code requires at least version 3.1\n"
#end

#declare L3Version = 1.4;
#declare L3Quality = 2;  // Quality level, 0=BBox, 1=no refr, 2=normal
#declare L3SW = 0.5;  // Width of seam between two bricks
#declare L3Bumps = 0;  // 1=on 0=off
#declare L3Ambient = 0.4;
#declare L3Diffuse = 0.4;
#declare L3Ior     = 1.25;
#declare L3NormalBumps = normal { bumps 0.01 scale 20 }
#declare L3SWT = (L3SW ? L3SW : 0.001);  // At least a small seam when transparent

#ifndef (L3FinishOpaque)
#declare L3FinishOpaque = finish {
	ambient L3Ambient
	diffuse L3Diffuse
	#if (L3Quality >= 2)
		phong 0.5
		phong_size 40
		reflection 0.08
	#end
}
#end
#ifndef (L3FinishTransparent)
#declare L3FinishTransparent = finish {
	ambient L3Ambient
	diffuse L3Diffuse
	#if (L3Quality >= 2)
		phong 0.5
		phong_size 40
		reflection 0.2
	#end
}
#end

#ifndef (L3TextureOpaqueRGB)
#macro L3TextureOpaqueRGB(r,g,b)
texture {
	pigment { rgb <r/255,g/255,b/255> }
	finish { L3FinishOpaque }
	#if (L3Bumps & (L3Quality > 1)) normal { L3NormalBumps } #end
}
#end
#end
#ifndef (L3TextureTransparentRGBA)
#macro L3TextureTransparentRGBA(r,g,b,a)
#local f = (a >= 128 ? 0.85 + (a-128) * 0.15 / (255-128) : a * 0.85 / 255);
texture {
	pigment { rgb <r/255,g/255,b/255> #if (L3Quality > 1) filter f #end }
	finish { L3FinishTransparent }
}
#end
#end
#ifndef (L3Material)
#macro L3Material(tex)
material {
	texture { tex }
}
#end
#end
#ifndef (L3MaterialT)
#macro L3MaterialT(tex)
material {
	texture { tex }
	#if (L3Quality > 1)
		interior { ior L3Ior }
	#end
}
#end
#end

//// Color 4 Red
#ifndef (L3Texture4)
#declare L3Texture4 = L3TextureOpaqueRGB(201,26,9)
#end
#ifndef (L3Color4)
#declare L3Color4 = L3Material(L3Texture4)
#end
//// Color 7 Light_Grey
#ifndef (L3Texture7)
#declare L3Texture7 = L3TextureOpaqueRGB(155,161,157)
#end
#ifndef (L3Color7)
#declare L3Color7 = L3Material(L3Texture7)
#end
//// Color 41 Trans_Medium_Blue
#ifndef (L3Texture41)
#declare L3Texture41 = L3TextureTransparentRGBA(85,154,183,128)
#end
#ifndef (L3Color41)
#declare L3Color41 = L3MaterialT(L3Texture41)
#end

//// Primitive box5.dat
#ifndef (box5_dot_dat)
#declare box5_dot_dat = object {
	mesh {
		triangle { <-1,1,1>, <1,1,1>, <1,1,-1> }
		triangle { <1,1,-1>, <-1,1,-1>, <-1,1,1> }
		triangle { <-1,1,1>, <-1,0,1>, <1,0,1> }
		triangle { <1,0,1>, <1,1,1>, <-1,1,1> }
		triangle { <-1,1,-1>, <-1,0,-1>, <-1,0,1> }
		triangle { <-1,0,1>, <-1,1,1>, <-1,1,-1> }
		triangle { <1,1,-1>, <1,0,-1>, <-1,0,-1> }
		triangle { <-1,0,-1>, <-1,1,-1>, <1,1,-1> }
		triangle { <1,1,1>, <1,0,1>, <1,0,-1> }
		triangle { <1,0,-1>, <1,1,-1>, <1,1,1> }
	}
}
#end // ifndef (box5_dot_dat)

//// Part 3003.dat: a brick 2 x 2 without studs
#ifndef (_3003_dot_dat)
#declare _3003_dot_dat = #if (L3Quality = 0) box { <-20,-4,-20>, <20,24,20> } #else union {
	object { box5_dot_dat matrix <16,0,0,0,-20,0,0,0,16,0,24,0> }
	mesh {
		triangle { <20,24,20>, <16,24,16>, <-16,24,16> }
		triangle { <-16,24,16>, <-20,24,20>, <20,24,20> }
		triangle { <-20,24,20>, <-16,24,16>, <-16,24,-16> }
		triangle { <-16,24,-16>, <-20,24,-20>, <-20,24,20> }
		triangle { <-20,24,-20>, <-16,24,-16>, <16,24,-16> }
		triangle { <16,24,-16>, <20,24,-20>, <-20,24,-20> }
		triangle { <20,24,-20>, <16,24,-16>, <16,24,16> }
		triangle { <16,24,16>, <20,24,20>, <20,24,-20> }
	}
	object { box5_dot_dat matrix <20,0,0,0,-24,0,0,0,20,0,24,0> }
}
#end
#end // ifndef (_3003_dot_dat)

//// Model
#ifndef (model_dot_ldr)
#declare model_dot_ldr = union {
	// 1 4  -30 0 0  1 0 0  0 1 0  0 0 1 3003.dat
	object {
		_3003_dot_dat
		matrix <1-L3SW/40,0,0,0,1-L3SW/28,0,0,0,1-L3SW/40,0,L3SW/2.8,0>
		matrix <1,0,0,0,1,0,0,0,1,-30,0,0>
		#if (version >= 3.1) material #else texture #end { L3Color4 }
	}
	// 1 41  20 0 10  1 0 0  0 1 0  0 0 1 3003.dat
	object {
		_3003_dot_dat
		matrix <1-L3SWT/40,0,0,0,1-L3SWT/28,0,0,0,1-L3SWT/40,0,L3SWT/2.8,0>
		matrix <1,0,0,0,1,0,0,0,1,20,0,10>
		#if (version >= 3.1) material #else texture #end { L3Color41 }
	}
	// 1 16  -5 -24 0  0.866 0 0.5  0 1 0  -0.5 0 0.866 3003.dat
	object {
		_3003_dot_dat
		matrix <1-L3SW/40,0,0,0,1-L3SW/28,0,0,0,1-L3SW/40,0,L3SW/2.8,0>
		matrix <0.866,0,-0.5,0,1,0,0.5,0,0.866,-5,-24,0>
	}
}
#end // ifndef (model_dot_ldr)

camera {
	#declare L3ViewingAngle = 60;
	#declare L3Sky = -y;
	sky      L3Sky
	right    -4/3*x
	#declare L3LookAt = <0,-14,0>;
	#declare L3Location = <60,-120,-160>;
	angle    L3ViewingAngle
	location L3Location
	look_at  L3LookAt
	rotate   <0,1e-5,0> // Prevent gap between adjacent quads
}

//// Lights
light_source {
	<-100,-300,-200>  // Latitude,Longitude,Radius
	color rgb <1,1,1>
}
light_source {
	<200,-250,-100>
	color rgb <0.6,0.6,0.6>
}

//// Floor
object {
	plane { y, 24 hollow }
	texture {
		pigment { color rgb <0.8,0.8,0.8> }
		finish { ambient L3Ambient diffuse L3Diffuse }
	}
}

//// ModelObject model.ldr
object { model_dot_ldr #if (version >= 3.1) material #else texture #end { L3Color7 } }
POV

# --- no #version: the rest of POV-Ray 3.6's rules POV-Ray 3.7 keeps ---------
cat >"$work/nover.pov" <<'POV'
// No #version, as many exporters write: POV-Ray 3.7 keeps its 3.6 rules
// for such a scene (EffectiveLanguageVersion 3.62): the background's
// transmit is not composited, the sky's filtering layers let the
// background through the 3.6 way, and a filtering surface's own light is
// 1 - (filter * max(r, g, b) + transmit). No assumed_gamma: gamma
// correction is off.
camera { location <0, 1.2, -4> look_at <0, 1, 0> }
light_source { <3, 6, -4> color rgb 1 }
background { rgbt <0.2, 0.4, 0.8, 0.5> }
sky_sphere {
  pigment { gradient y color_map { [0.3 rgbf <0.8, 0.8, 1, 0.6>] [0.9 rgbt <0.1, 0.1, 0.4, 0.3>] } }
}
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.3, 0.4, 0.3> } }
box { <-1.6, 0, -0.5>, <-0.2, 1.4, 0.5> pigment { rgbf <0.8, 0.3, 0.2, 0.85> } finish { ambient 0.4 diffuse 0.4 phong 0.5 reflection 0.2 } interior { ior 1.25 } }
box { <0.2, 0, -0.5>, <1.6, 1.4, 0.5> pigment { rgbft <0.2, 0.5, 0.7, 0.5, 0.3> } finish { ambient 0.3 diffuse 0.5 } }
POV

# --- textures per vertex, all three the same ---------------------------------
# POV-Ray blends a face's three textures by weight (Mesh::Determine_Textures),
# which for one texture three times differs from it by rounding: the RMSE.
cat >"$work/vcol.pov" <<'POV'
// Per-vertex textures as vertex-colour exporters (three.js's POVExporter,
// vispy) write them: a texture_list of colours and three indices per face,
// here the same three on each face; and a mesh triangle's texture_list of
// three declared textures (POV-Ray's Parse_Mesh_Texture), the same three.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
#declare surface1 = mesh2 {
vertex_vectors {
  5,
  <-2,0,0>,
  <-1,0,0>,
  <-1.5,1.5,0>,
  <-0.5,1.5,0.5>,
  <-2.2,1.4,0.5>,
  }
texture_list {
  3,
texture{pigment{rgb <0.9,0.2,0.1>}}
texture{pigment{rgb <0.1,0.7,0.2>}}
texture{pigment{rgb <0.2,0.3,0.9>}}
}
face_indices {
  3,
  <0,1,2>, 0, 0, 0
  <1,3,2>, 1, 1, 1
  <0,2,4>, 2, 2, 2
  }
}
union {
  object { surface1 }
  pigment{rgb 1}
}
#declare Gold = texture { pigment { rgb <1, 0.8, 0.3> } finish { phong 0.6 } }
mesh {
  triangle { <0.5,0,0>, <2,0,0>, <1.2,1.6,0.3> texture_list { Gold, Gold, Gold } }
  triangle { <0.5,0,0>, <1.2,1.6,0.3>, <0.3,1.2,0.6> texture_list { Gold Gold Gold } }
}
POV

# --- textures per vertex, three different ones ------------------------------
# POV-Ray shades each of a face's three textures whole, the lights once
# for all (its light colour cache), and blends the shaded colours by the
# point's barycentric weights (Mesh::Determine_Textures, ComputeTextureColour;
# a weight below adc_bailout is left out); a shadow ray through the face is
# filtered by the three textures' filters blended the same way
# (ComputeShadowColour). Different finishes and see-through textures among
# them, in a mesh2 and in mesh triangles' texture_lists.
cat >"$work/vtex.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
light_source { <3, 6, -4> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
#declare surface1 = mesh2 {
vertex_vectors {
  5,
  <-2,0,0>,
  <-1,0,0>,
  <-1.5,1.5,0>,
  <-0.5,1.5,0.5>,
  <-2.2,1.4,0.5>,
  }
texture_list {
  3,
texture{pigment{rgb <0.9,0.2,0.1>}}
texture{pigment{rgb <0.1,0.7,0.2>} finish { phong 0.8 }}
texture{pigment{rgbf <0.2,0.3,0.9,0.7>}}
}
face_indices {
  3,
  <0,1,2>, 0, 1, 2
  <1,3,2>, 1, 2, 0
  <0,2,4>, 2, 0, 1
  }
}
union {
  object { surface1 }
  pigment{rgb 1}
}
#declare Gold = texture { pigment { rgb <1, 0.8, 0.3> } finish { phong 0.6 } }
#declare Glass = texture { pigment { rgbf <0.7, 0.9, 1, 0.8> } finish { reflection 0.2 } }
#declare Red = texture { pigment { rgb <0.9, 0.1, 0.1> } }
mesh {
  triangle { <0.5,0,0>, <2,0,0>, <1.2,1.6,0.3> texture_list { Gold, Glass, Red } }
  triangle { <0.5,0,0>, <1.2,1.6,0.3>, <0.3,1.2,0.6> texture_list { Red Gold Glass } }
  interior { ior 1.3 }
}
POV

# --- LeoCAD with LGEO-like materials: transparent parts whose interiors fade
# POV-Ray 3.7 fades a shadow ray through a fading interior by the law it
# applies to rays seen through it (trace.cpp, ComputeShadowTexture), over
# the legs between the surfaces of the interior that the ray passes, which
# enter and leave it in turn (ComputeShadowMedia). The bricks' shadows on
# the plate and on each other cross such interiors. Two bricks of one
# declared material are stacked, the lower one's studs inside the upper
# one: each use of a declared material has an interior of its own
# (Parse_Material copies it), so rays pass from one into the other. What is
# left is the refracted rays' ties at the triangles' shared edges (a few
# pixels).
cat >"$work/leocad.pov" <<'POV'
// In the style of LeoCAD's POV-Ray export with LGEO-like materials: colour
// textures declared as lc_ names, transparent colours as materials whose
// interior fades, parts declared as unions of meshes of smooth triangles
// (face normals, as LeoCAD writes them), each placed by object { part
// material matrix }, z up, the camera's sky along the model's up.
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 10
}

#declare lg_ior = 1.25;
#declare lc_Red = texture { pigment { rgb <0.788235, 0.101961, 0.035294> } finish { ambient 0.1 phong 0.2 phong_size 20 } }
#declare lc_Light_Grey = texture { pigment { rgb <0.607843, 0.631373, 0.615686> } finish { ambient 0.1 phong 0.2 phong_size 20 } }
#declare lc_Green = texture { pigment { rgb <0.145098, 0.478431, 0.243137> } finish { ambient 0.1 phong 0.2 phong_size 20 } }
#declare lc_Trans_Red = material {
  texture { pigment { rgb <0.788235, 0.101961, 0.035294> filter 0.85 } finish { ambient 0.3 diffuse 0.2 reflection 0.25 phong 0.3 phong_size 60 } }
  interior { ior lg_ior fade_distance 0.6 fade_power 2 fade_colour <0.8, 0.1, 0.05> }
}
#declare lc_Trans_Clear = material {
  texture { pigment { rgb <0.988235, 0.988235, 0.988235> filter 0.9 } finish { ambient 0.3 diffuse 0.2 reflection 0.25 phong 0.3 phong_size 60 } }
  interior { ior lg_ior fade_distance 1.2 fade_power 1001 }
}

// a 2x2 brick: its shell, and one stud (open below, as LDraw's) placed four times
#declare lc_box = mesh {
  smooth_triangle { <-0.4, -0.4, 0>, <0, 0, -1>, <0.4, -0.4, 0>, <0, 0, -1>, <0.4, 0.4, 0>, <0, 0, -1> }
  smooth_triangle { <-0.4, -0.4, 0>, <0, 0, -1>, <0.4, 0.4, 0>, <0, 0, -1>, <-0.4, 0.4, 0>, <0, 0, -1> }
  smooth_triangle { <-0.4, -0.4, 0.96>, <0, 0, 1>, <0.4, 0.4, 0.96>, <0, 0, 1>, <0.4, -0.4, 0.96>, <0, 0, 1> }
  smooth_triangle { <-0.4, -0.4, 0.96>, <0, 0, 1>, <-0.4, 0.4, 0.96>, <0, 0, 1>, <0.4, 0.4, 0.96>, <0, 0, 1> }
  smooth_triangle { <-0.4, -0.4, 0>, <0, -1, 0>, <0.4, -0.4, 0.96>, <0, -1, 0>, <0.4, -0.4, 0>, <0, -1, 0> }
  smooth_triangle { <-0.4, -0.4, 0>, <0, -1, 0>, <-0.4, -0.4, 0.96>, <0, -1, 0>, <0.4, -0.4, 0.96>, <0, -1, 0> }
  smooth_triangle { <-0.4, 0.4, 0>, <0, 1, 0>, <0.4, 0.4, 0>, <0, 1, 0>, <0.4, 0.4, 0.96>, <0, 1, 0> }
  smooth_triangle { <-0.4, 0.4, 0>, <0, 1, 0>, <0.4, 0.4, 0.96>, <0, 1, 0>, <-0.4, 0.4, 0.96>, <0, 1, 0> }
  smooth_triangle { <-0.4, -0.4, 0>, <-1, 0, 0>, <-0.4, 0.4, 0>, <-1, 0, 0>, <-0.4, 0.4, 0.96>, <-1, 0, 0> }
  smooth_triangle { <-0.4, -0.4, 0>, <-1, 0, 0>, <-0.4, 0.4, 0.96>, <-1, 0, 0>, <-0.4, -0.4, 0.96>, <-1, 0, 0> }
  smooth_triangle { <0.4, -0.4, 0>, <1, 0, 0>, <0.4, 0.4, 0.96>, <1, 0, 0>, <0.4, 0.4, 0>, <1, 0, 0> }
  smooth_triangle { <0.4, -0.4, 0>, <1, 0, 0>, <0.4, -0.4, 0.96>, <1, 0, 0>, <0.4, 0.4, 0.96>, <1, 0, 0> }
}
#declare lc_stud = mesh {
  smooth_triangle { <0.12, 0, 0>, <1, 0, 0>, <0.085, 0.085, 0>, <0.707, 0.707, 0>, <0.085, 0.085, 0.16>, <0.707, 0.707, 0> }
  smooth_triangle { <0.12, 0, 0>, <1, 0, 0>, <0.085, 0.085, 0.16>, <0.707, 0.707, 0>, <0.12, 0, 0.16>, <1, 0, 0> }
  smooth_triangle { <0.085, 0.085, 0>, <0.707, 0.707, 0>, <0, 0.12, 0>, <0, 1, 0>, <0, 0.12, 0.16>, <0, 1, 0> }
  smooth_triangle { <0.085, 0.085, 0>, <0.707, 0.707, 0>, <0, 0.12, 0.16>, <0, 1, 0>, <0.085, 0.085, 0.16>, <0.707, 0.707, 0> }
  smooth_triangle { <0, 0.12, 0>, <0, 1, 0>, <-0.085, 0.085, 0>, <-0.707, 0.707, 0>, <-0.085, 0.085, 0.16>, <-0.707, 0.707, 0> }
  smooth_triangle { <0, 0.12, 0>, <0, 1, 0>, <-0.085, 0.085, 0.16>, <-0.707, 0.707, 0>, <0, 0.12, 0.16>, <0, 1, 0> }
  smooth_triangle { <-0.085, 0.085, 0>, <-0.707, 0.707, 0>, <-0.12, 0, 0>, <-1, 0, 0>, <-0.12, 0, 0.16>, <-1, 0, 0> }
  smooth_triangle { <-0.085, 0.085, 0>, <-0.707, 0.707, 0>, <-0.12, 0, 0.16>, <-1, 0, 0>, <-0.085, 0.085, 0.16>, <-0.707, 0.707, 0> }
  smooth_triangle { <-0.12, 0, 0>, <-1, 0, 0>, <-0.085, -0.085, 0>, <-0.707, -0.707, 0>, <-0.085, -0.085, 0.16>, <-0.707, -0.707, 0> }
  smooth_triangle { <-0.12, 0, 0>, <-1, 0, 0>, <-0.085, -0.085, 0.16>, <-0.707, -0.707, 0>, <-0.12, 0, 0.16>, <-1, 0, 0> }
  smooth_triangle { <-0.085, -0.085, 0>, <-0.707, -0.707, 0>, <0, -0.12, 0>, <0, -1, 0>, <0, -0.12, 0.16>, <0, -1, 0> }
  smooth_triangle { <-0.085, -0.085, 0>, <-0.707, -0.707, 0>, <0, -0.12, 0.16>, <0, -1, 0>, <-0.085, -0.085, 0.16>, <-0.707, -0.707, 0> }
  smooth_triangle { <0, -0.12, 0>, <0, -1, 0>, <0.085, -0.085, 0>, <0.707, -0.707, 0>, <0.085, -0.085, 0.16>, <0.707, -0.707, 0> }
  smooth_triangle { <0, -0.12, 0>, <0, -1, 0>, <0.085, -0.085, 0.16>, <0.707, -0.707, 0>, <0, -0.12, 0.16>, <0, -1, 0> }
  smooth_triangle { <0.085, -0.085, 0>, <0.707, -0.707, 0>, <0.12, 0, 0>, <1, 0, 0>, <0.12, 0, 0.16>, <1, 0, 0> }
  smooth_triangle { <0.085, -0.085, 0>, <0.707, -0.707, 0>, <0.12, 0, 0.16>, <1, 0, 0>, <0.085, -0.085, 0.16>, <0.707, -0.707, 0> }
  triangle { <0, 0, 0.16>, <0.12, 0, 0.16>, <0.085, 0.085, 0.16> }
  triangle { <0, 0, 0.16>, <0.085, 0.085, 0.16>, <0, 0.12, 0.16> }
  triangle { <0, 0, 0.16>, <0, 0.12, 0.16>, <-0.085, 0.085, 0.16> }
  triangle { <0, 0, 0.16>, <-0.085, 0.085, 0.16>, <-0.12, 0, 0.16> }
  triangle { <0, 0, 0.16>, <-0.12, 0, 0.16>, <-0.085, -0.085, 0.16> }
  triangle { <0, 0, 0.16>, <-0.085, -0.085, 0.16>, <0, -0.12, 0.16> }
  triangle { <0, 0, 0.16>, <0, -0.12, 0.16>, <0.085, -0.085, 0.16> }
  triangle { <0, 0, 0.16>, <0.085, -0.085, 0.16>, <0.12, 0, 0.16> }
}
#declare lc_3003_dat = union {
  object { lc_box }
  object { lc_stud matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, -0.2, -0.2, 0.96> }
  object { lc_stud matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, -0.2, 0.96> }
  object { lc_stud matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, -0.2, 0.2, 0.96> }
  object { lc_stud matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, 0.96> }
}
#declare lc_3811_dat = mesh {
  smooth_triangle { <-3, -3, -0.34>, <0, 0, 1>, <3, 3, -0.34>, <0, 0, 1>, <3, -3, -0.34>, <0, 0, 1> }
  smooth_triangle { <-3, -3, -0.34>, <0, 0, 1>, <-3, 3, -0.34>, <0, 0, 1>, <3, 3, -0.34>, <0, 0, 1> }
}

camera {
  perspective
  right -x * image_width / image_height
  sky <-0.3, 0.3, 0.9>
  location <3.6, -3.4, 3.9>
  look_at <0, 0, 0.5>
  angle 40 * image_width / image_height
}

background { color rgb <1, 1, 1> }

light_source { <1.8, -2.6, 6.0> color rgb 0.75 }
light_source { <-4.0, -1.5, 3.0> color rgb 0.5 }

object { lc_3811_dat texture { lc_Green } matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> }
object { lc_3003_dat texture { lc_Red } matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, -1.2, 0.8, -0.32> }
object { lc_3003_dat texture { lc_Light_Grey } matrix <0.866, 0.5, 0, -0.5, 0.866, 0, 0, 0, 1, 1.1, 1.0, -0.32> }
object { lc_3003_dat material { lc_Trans_Clear } matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -0.32> }
object { lc_3003_dat material { lc_Trans_Red } matrix <0.966, -0.259, 0, 0.259, 0.966, 0, 0, 0, 1, 0.2, -0.9, -0.32> }
object { lc_3003_dat material { lc_Trans_Clear } matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, -0.2, 0.2, 0.66> }
POV

# --- fading interiors and fake caustics, bare ------------------------------
# Both fades (power 2 with a colour, and the exponential power 1001) and a
# finish's caustics, which POV-Ray 3.7 moves to the interior unscaled
# (Post_Process), multiplying the light through the box by 1 + |cos|^1;
# the light an area light (at +Q9), each sample's shadow ray faded.
cat >"$work/fading.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 6, -9> look_at <0, 0.5, 0> angle 45 }
light_source { <3, 10, -4> color rgb 1 area_light <1.5, 0, 0>, <0, 0, 1.5>, 3, 3 }
box { <-6, -1, -6>, <6, 0, 6> pigment { rgb <0.9, 0.9, 0.8> } }
box { <-2.5, 0.5, -1>, <-0.5, 2.5, 1>
  pigment { rgbf <1, 0.4, 0.3, 0.9> } finish { phong 0.5 }
  interior { ior 1.0 fade_distance 1 fade_power 2 fade_colour <0.8, 0.2, 0.1> } }
box { <0.5, 0.5, -1>, <2.5, 1.5, 1>
  pigment { rgbt <0.3, 0.5, 1, 0.45> } finish { caustics 1.0 }
  interior { ior 1.5 fade_distance 0.7 fade_power 1001 } }
POV

# --- a declared glass object placed twice, the copies overlapping -----------
# POV-Ray's Copy_Object gives each copy an interior of its own: a ray from
# one into the other enters the second (its ior, its fade) while inside the
# first.
cat >"$work/declared.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 5, -8> look_at <0, 0.8, 0> angle 45 }
light_source { <2, 10, -3> color rgb 1 }
box { <-6, -1, -6>, <6, 0, 6> pigment { rgb <0.9, 0.9, 0.8> } }
#declare Pane = object { box { <-1, 0.2, -1>, <1, 1.4, 1> }
  pigment { rgbf <0.6, 0.8, 1, 0.9> } interior { ior 1.3 fade_distance 0.6 fade_power 2 fade_colour <0.2, 0.4, 0.8> } }
object { Pane translate <-0.6, 0, 0> }
object { Pane rotate y*20 translate <0.6, 0.5, 0.3> }
POV

# --- under water: a plane's fading interior ---------------------------------
# A point under the water plane (found by a ray refracted into it) starts
# its shadow ray inside the plane's interior: the light fades at the
# surface over the leg from the last see-through surface before it (here
# the orange box's, which stands out of the water), or from the point; and
# the box's own fading interior is crossed by the surface, where the leg of
# the light inside the box starts again.
cat >"$work/water.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 3, -6> look_at <0, -0.5, 0> angle 55 }
light_source { <3, 8, -3> color rgb 1 }
plane { y, -2 pigment { checker rgb <0.9, 0.85, 0.7> rgb <0.5, 0.45, 0.4> } }
plane { y, 0 pigment { rgbf <0.8, 0.9, 1, 0.9> } finish { reflection 0.1 }
  interior { ior 1.33 fade_distance 1.5 fade_power 2 fade_colour <0.1, 0.5, 0.6> } }
box { <-0.5, -1.9, -0.5>, <0.5, 0.8, 0.5> pigment { rgbf <1, 0.5, 0.3, 0.8> }
  interior { ior 1.0 fade_distance 0.5 fade_power 1001 } rotate y*30 translate <1, 0, 0.5> }
box { <-0.4, -2, -0.4>, <0.4, 1, 0.4> pigment { rgb <0.3, 0.6, 0.3> } translate <-1.5, 0, 1> }
POV

# --- Blender's exporter with caustics and photons on ------------------------
# photons { } on the objects and the lamp, an object a target, but no
# global photons block: POV-Ray 3.7 maps no photons (it shoots them only
# where global_settings turns photon mapping on, and only at targets), so
# the image is the one without; the interior's fake caustics (45 times the
# value written) and fade, and dispersion 1 (none), are rendered exactly.
cat >"$work/blendph.pov" <<'POV'
//----------------------------------------------------------------
//--In the style of Blender's POV-Ray exporter, caustics enabled--
//----------------------------------------------------------------
#version 3.7;

//--Global settings--
global_settings {
    assumed_gamma 1.0
    max_trace_level 8
    ambient_light rgb<0.2, 0.2, 0.2>
}

//--Background--
background {rgbt<0.05, 0.06, 0.08, 0>}

//--Cameras--
camera {
    location  <0, 0, 0>
    look_at  <0, 0, -1>
    right <-1.3333333333333333, 0, 0>
    up <0, 1, 0>
    angle  49.134343
    rotate  <-30.0, 40.0, 0.0>
    translate <5.2, 5.0, 6.4>
}

//--Lamps--
light_source {
    < 0,0,0 >
    color rgb<1.0, 1.0, 1.0>
    photons{
        refraction on
        reflection on
    }
    translate <-4.0, 4.5, -1.0>
}

//--Material Definitions--
#declare shader_Glass = finish {
    diffuse 0.3 0
    phong 0.6
    phong_size 60
    ambient 0.2
    emission 0
}
#declare shader_Floor = finish {
    diffuse 0.8 0
    ambient 0.2
}

//--Mesh objects--
#declare DATAGlass =
mesh2 {
    vertex_vectors {
        8,
        <1, 1, -1>, <1, -1, -1>, <-1, -1, -1>, <-1, 1, -1>,
        <1, 1, 1>, <1, -1, 1>, <-1, -1, 1>, <-1, 1, 1>
    }
    texture_list {
        1
        texture {
            pigment {rgbft<0.7, 0.85, 0.95, 0.5, 0>}
            finish {shader_Glass}
        }
    }
    face_indices {
        12,
        <0,1,2>, 0,0,0,
        <0,2,3>, 0,0,0,
        <4,7,6>, 0,0,0,
        <4,6,5>, 0,0,0,
        <0,4,5>, 0,0,0,
        <0,5,1>, 0,0,0,
        <1,5,6>, 0,0,0,
        <1,6,2>, 0,0,0,
        <2,6,7>, 0,0,0,
        <2,7,3>, 0,0,0,
        <4,0,3>, 0,0,0,
        <4,3,7>, 0,0,0
    }
    interior {
        ior 1.450000
        caustics 0.200
        dispersion 1.000000
        dispersion_samples 7
        fade_distance 2.5
        fade_power 1
    }
    photons{
        target
        refraction on
        reflection on
        collect on
    }
}
object {
    DATAGlass
    matrix <1, 0, 0,  0, 1, 0,  0, 0, 1,  0, 1.01, 0>
}
#declare DATAPlane =
mesh2 {
    vertex_vectors { 4, <-6,-6,0>, <6,-6,0>, <6,6,0>, <-6,6,0> }
    texture_list { 1 texture { pigment {rgbft<0.7, 0.7, 0.7, 0, 0>} finish {shader_Floor} } }
    face_indices { 2, <0,1,2>, 0,0,0, <0,2,3>, 0,0,0 }
    photons{
        collect on
    }
}
object {
    DATAPlane
    matrix <1,0,0, 0,0,-1, 0,1,0, 0,0,0>
}
POV

# The limits per scene, 240x180 (the rule of tests/regress.sh): each LIMIT
# (MEASURED) pair is the limit and the value measured on 2026-12-07 against
# POV-Ray 3.7.0.10 (one thread; the same in two runs), about the larger of
# twice that and 1e-5 for an RMSE, twice that and 1 for a count of pixels:
# the full +Q9 image's RMSE and its pixels off by more than 0.02, and the
# shadow-mask pixels that disagree (at edges and silhouettes; none may in
# the interior). leocad, fading, blendph, vtex, water and declared were
# measured on 2026-12-07 too, when added.
limits='
# scene       RMSE   (measured)   off (m.)  mask pixels (m.)
ldcad         1e-5   (3.53e-6)    1 (0)     1 (0)
blender       3.8e-4 (1.90e-4)    1 (0)     1 (0)
toplevel      1e-5   (1.92e-6)    1 (0)     1 (0)
l3p           1e-5   (4.76e-6)    1 (0)     1 (0)
nover         7.7e-5 (3.84e-5)    1 (0)     1 (0)
vcol          6.8e-5 (3.40e-5)    1 (0)     1 (0)
leocad        1.2e-3 (5.86e-4)    10 (5)    2 (1)
fading        2.4e-5 (1.16e-5)    1 (0)     1 (0)
blendph       3.6e-4 (1.79e-4)    4 (2)     1 (0)
vtex          1e-5   (3.33e-6)    1 (0)     1 (0)
water         1.2e-4 (5.73e-5)    1 (0)     1 (0)
declared      4e-5   (1.96e-5)    1 (0)     1 (0)
'
scenes="ldcad blender toplevel l3p nover vcol leocad fading blendph vtex water declared"
# shellcheck disable=SC2086 # the names, one word each
povray_scenes_check "$limits" tests/exporter-syntax.sh $scenes

# --- mistakes near those forms ----------------------------------------------
# Each: status 2, the message at FILE:LINE:COLUMN, no image.
while IFS='|' read -r scene message; do
    printf '%s\n' "$scene" >"$work/bad.pov"
    rm -f "$work/bad.png"
    run "$work/bad.pov" --width 8 --height 6 -o "$work/bad.png"
    check "$message: status 2, FILE:LINE:COLUMN, no image" \
        test "$status $(grep -c "^$work/bad.pov:[0-9]*:[0-9]*: .*$message" "$work/err") $([ -e "$work/bad.png" ] && echo image || echo none)" = "2 1 none"
done <<'BAD'
#declare T = texture { pigment { rgb 1 } } T|'T' cannot stand alone here
Model|undeclared identifier 'Model'
#declare S = ovus { 1, 0.5 } S|'ovus' is not supported by hstrace (declared at
#declare S = ovus { 1, 0.5 } union { triangle { 0, x, y } S }|'ovus' is not supported by hstrace (declared at
#declare T = triangle { 0, x, y } union { T object { T } }|expected an object modifier or '}' in 'object', found 'object'
triangle { 0, x, y pigment { rgb 1 } finish { subsurface { translucency 0.5 scattering 1 } } }|expected translucency, anisotropy or '}' in 'subsurface', found 'scattering'
triangle { 0, x, y pigment { rgb 1 } finish { diffuse 0.6 0.2 0.1 } }|expected a finish item or '}' in 'finish', found '0.1'
#declare P = pigment { rgb 1 } mesh { triangle { 0, x, y texture_list { P, P, P } } }|'P' cannot be used in a texture_list
BAD
# Three different textures on a face, one per vertex (vtex, above, rendered
# against POV-Ray): --strict accepts them, and the same three too. A
# texture_map among them is not blended (the first vertex's texture shows
# on the whole face): reported at the first such face, refused by --strict
# where the declared mesh is used, or at once in a mesh triangle's
# texture_list.
run "$work/vtex.pov" --width 8 --height 6 --strict -o "$work/vtex-strict.png"
check "three different plain textures per vertex: --strict renders, nothing reported" \
    test "$status $(wc -c <"$work/err" | tr -d ' ')" = "0 0"
run "$work/vcol.pov" --width 8 --height 6 --strict -o "$work/vcol-strict.png"
check "the same three textures per vertex: nothing reported, not refused by --strict" \
    test "$status $(wc -c <"$work/err" | tr -d ' ')" = "0 0"
sed 's/^texture{pigment{rgbf <0.2,0.3,0.9,0.7>}}$/texture{ checker texture { pigment { rgb 1 } } texture { pigment { rgbf <0.2,0.3,0.9,0.7> } } scale 0.2 }/' \
    "$work/vtex.pov" >"$work/vtexmap.pov"
run "$work/vtexmap.pov" --width 8 --height 6 -o "$work/vtexmap.png"
check "mesh2 faces with a texture_map among their textures per vertex: render, reported as approximated at the first" \
    exited 0 "^$work/vtexmap.pov:23:15: warning: 'a texture per vertex' approximated: a texture_map among"
run "$work/vtexmap.pov" --width 8 --height 6 --strict -o "$work/vtexmap-strict.png"
check "... refused with --strict where the declared mesh is used, status 2, naming the face" \
    exited 2 "^$work/vtexmap.pov:29:12: 'a texture per vertex' is only approximated by hstrace; --strict makes it an error (declared at $work/vtexmap.pov:23)"
sed 's/^#declare Glass = .*/#declare Glass = texture { checker texture { Gold } texture { Red } }/; s/^#declare Red = .*//; s/^#declare Gold = .*/&\n#declare Red = texture { pigment { rgb <0.9, 0.1, 0.1> } }/' \
    "$work/vtex.pov" >"$work/vtexmap2.pov"
run "$work/vtexmap2.pov" --width 8 --height 6 --strict -o "$work/vtexmap2.png"
check "a mesh triangle's texture_list with a texture_map: refused with --strict, status 2" \
    exited 2 "^$work/vtexmap2.pov:[0-9]*:[0-9]*: 'a texture per vertex' is only approximated"

# photons: accepted by --strict where they change nothing in POV-Ray's image
# (blendph, above: rendered with --strict here, nothing reported); once
# global_settings turns photon mapping on for its target, POV-Ray's image
# has caustics hstrace does not compute: reported, refused by --strict at
# the first photons { } counted (the objects' before the lights').
run "$work/blendph.pov" --width 8 --height 6 --strict -o "$work/blendph-strict.png"
check "photons { } on objects and the lamp, a target, no global photons: --strict renders, nothing reported" \
    test "$status $(wc -c <"$work/err" | tr -d ' ')" = "0 0"
sed 's/^    ambient_light rgb<0.2, 0.2, 0.2>$/&\n    photons { count 20000 }/' "$work/blendph.pov" >"$work/blendph-on.pov"
target_line=$(grep -n '^        target$' "$work/blendph-on.pov" | cut -d: -f1)
run "$work/blendph-on.pov" --width 8 --height 6 --strict -o "$work/blendph-on.png"
check "... with global photons: refused by --strict at the target's photons { }, status 2" \
    exited 2 "^$work/blendph-on.pov:$((target_line - 1)):5: 'photons' is only approximated by hstrace (photon mapping ignored: global_settings turns it on and an object is a target)"
run "$work/blendph-on.pov" --width 8 --height 6 -o "$work/blendph-on.png"
check "... and reported without --strict: the three photons { } blocks and the global one" \
    exited 0 "^$work/blendph-on.pov:$((target_line - 1)):5: warning: 'photons' approximated: photon mapping ignored (4 places; --strict refuses it)"

# A backside diffuse other than 0 lights the surface from behind, which
# hstrace does not model: reported, and refused by --strict.
printf 'camera { location <0,0,-3> look_at 0 }\nlight_source { <2,4,-3> rgb 1 }\ntriangle { <-1,-1,0>, <1,-1,0>, <0,1,0> pigment { rgb 1 } finish { diffuse 0.6 0.3 } }\n' >"$work/back.pov"
run "$work/back.pov" --width 8 --height 6 -o "$work/back.png"
check "diffuse 0.6 0.3: renders, the backside reported as approximated at FILE:LINE:COLUMN" \
    exited 0 "^$work/back.pov:3:80: warning: 'diffuse's backside value' approximated"
run "$work/back.pov" --width 8 --height 6 --strict -o "$work/back-strict.png"
check "... refused with --strict, status 2" exited 2 "^$work/back.pov:3:80: 'diffuse's backside value' is only approximated"
tap_end
