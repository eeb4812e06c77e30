#include "page/html_page.hpp"

#include "core/text/markdown_html.hpp"

namespace haptex::page {
namespace {

constexpr const char* kStyle = R"(body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;line-height:1.45;color:#222}
table{border-collapse:collapse;margin:1em 0;font-size:.9em}th,td{border:1px solid #ccc;padding:.25em .5em;text-align:left}
th{background:#f3f3f3;cursor:pointer}th.sorted-up::after{content:" \25B2"}th.sorted-down::after{content:" \25BC"}
code{background:#f5f5f5;padding:0 .2em}figure{margin:1em 0}img{max-width:100%}
.material{border-top:1px solid #ddd;padding:.5em 0}.material .row{display:flex;gap:1.5em;flex-wrap:wrap;align-items:flex-start}
.material svg{background:#fafafa;border:1px solid #ddd}#load-check{display:none})";

// Sorting by the column clicked (numbers as numbers), and the load check.
constexpr const char* kScript = R"(document.querySelectorAll("table.sortable th").forEach(function(th){th.addEventListener("click",function(){
var table=th.closest("table"),body=table.tBodies[0],i=Array.prototype.indexOf.call(th.parentNode.children,th);
var up=!th.classList.contains("sorted-up");table.querySelectorAll("th").forEach(function(h){h.classList.remove("sorted-up","sorted-down")});
th.classList.add(up?"sorted-up":"sorted-down");var key=function(r){var t=r.children[i]?r.children[i].textContent.trim():"";var n=parseFloat(t);return isNaN(n)?t:n};
Array.prototype.slice.call(body.rows).sort(function(a,b){var x=key(a),y=key(b);var c=(typeof x==typeof y)?(x<y?-1:x>y?1:0):(typeof x=="number"?-1:1);return up?c:-c}).forEach(function(r){body.appendChild(r)})})});
(function(){var check={images:0,image_errors:[],audio:[],audio_errors:[]};var out=document.getElementById("load-check");
var images=document.querySelectorAll("img"),audio=document.querySelectorAll("audio"),waiting=images.length+audio.length;
function finish(){out.textContent=JSON.stringify(check);out.setAttribute("data-done","1")}function done(){if(--waiting<=0)finish()}
if(waiting==0)finish();
images.forEach(function(img){function ok(){check.images++;done()}function bad(){check.image_errors.push(img.alt);done()}
if(img.complete){img.naturalWidth>0?ok():bad()}else{img.addEventListener("load",ok);img.addEventListener("error",bad)}});
audio.forEach(function(a){function ok(){check.audio.push({title:a.title,seconds:a.duration});done()}function bad(){check.audio_errors.push(a.title);done()}
if(a.readyState>=1){ok()}else{a.addEventListener("loadedmetadata",ok);a.addEventListener("error",bad)}a.load()})})();)";

}  // namespace

std::string html_page(const std::string& title, const std::string& body) {
  return "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + text::html_escaped(title) + "</title><style>" +
         kStyle + "</style></head><body>\n" + body + "<pre id=\"load-check\"></pre>\n<script>" + kScript + "</script>\n</body></html>\n";
}

}  // namespace haptex::page
