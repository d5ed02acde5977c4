// The Operation Objects of api/openapi/operation_docs.h: one per operationId of the API, every
// response body a named schema, writes behind the bearer scheme, and the model parameters
// documented with the ranges of every registered model's descriptor.
#include "api/openapi/operation_docs.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>

#include "models/registry.h"

namespace clearsky::api {
namespace {

using Json = nlohmann::ordered_json;

const char* const kOperationIds[] = {"healthz",
                                     "readyz",
                                     "metrics",
                                     "openapi",
                                     "listModels",
                                     "getSun",
                                     "getRadiance",
                                     "postRadiance",
                                     "getIrradiance",
                                     "getRgb",
                                     "postRgb",
                                     "getSkydome",
                                     "getSkyPatches",
                                     "listDatasets",
                                     "importDataset",
                                     "getDataset",
                                     "deleteDataset",
                                     "listImports",
                                     "getImport",
                                     "listEvaluations",
                                     "createEvaluation",
                                     "getEvaluation",
                                     "getEvaluationTicket",
                                     "listFits",
                                     "createFit",
                                     "getFit",
                                     "listAerosols",
                                     "uploadAerosols",
                                     "getAerosols",
                                     "listJobs",
                                     "createJob",
                                     "getJob",
                                     "deleteJob",
                                     "pauseJob",
                                     "resumeJob"};

const Json& resolve(const Json& components, const Json& node) {
  if (!node.contains("$ref")) return node;
  const std::string ref = node["$ref"];
  const std::string prefix = "#/components/";
  EXPECT_EQ(ref.rfind(prefix, 0), 0u) << ref;
  return components.at(Json::json_pointer("/" + ref.substr(prefix.size())));
}

TEST(OperationDocs, EveryOperationIsDocumented) {
  for (const char* id : kOperationIds) {
    const Json* operation = operation_doc(id);
    ASSERT_NE(operation, nullptr) << id;
    EXPECT_EQ((*operation)["operationId"], id);
    EXPECT_FALSE((*operation)["summary"].get<std::string>().empty()) << id;
    EXPECT_FALSE((*operation)["tags"].empty()) << id;
    EXPECT_TRUE((*operation)["responses"].contains("500")) << id;
  }
  EXPECT_EQ(operation_doc("noSuchOperation"), nullptr);
}

TEST(OperationDocs, EveryTagIsDescribed) {
  std::set<std::string> described;
  for (const auto& tag : openapi_tags()) {
    EXPECT_FALSE(tag["description"].get<std::string>().empty()) << tag;
    described.insert(tag["name"].get<std::string>());
  }
  std::set<std::string> used;
  for (const char* id : kOperationIds)
    for (const auto& tag : (*operation_doc(id))["tags"]) used.insert(tag.get<std::string>());
  EXPECT_EQ(used, described);
}

TEST(OperationDocs, EveryResponseBodyIsANamedSchema) {
  const Json components = openapi_components();
  for (const char* id : kOperationIds) {
    for (const auto& [status, entry] : (*operation_doc(id))["responses"].items()) {
      const Json& response = resolve(components, entry);
      EXPECT_FALSE(response["description"].get<std::string>().empty()) << id << " " << status;
      if (status == "304") {
        EXPECT_FALSE(response.contains("content")) << id;
        continue;
      }
      ASSERT_TRUE(response.contains("content")) << id << " " << status;
      for (const auto& [media_type, media] : response["content"].items()) {
        const std::string ref = media["schema"].value("$ref", "");
        ASSERT_EQ(ref.rfind("#/components/schemas/", 0), 0u) << id << " " << status;
        EXPECT_TRUE(components["schemas"].contains(ref.substr(21))) << ref;
        if (status[0] == '4' || status[0] == '5') {
          if (!(id == std::string("readyz") && status == "503")) {
            EXPECT_EQ(ref, "#/components/schemas/Error") << id << " " << status;
          }
        }
      }
      if (status == "503" || status == "429") {
        EXPECT_TRUE(response["headers"].contains("Retry-After")) << id << " " << status;
      }
    }
  }
}

TEST(OperationDocs, WritesNeedTheBearerToken) {
  const std::set<std::string> writes = {"importDataset", "deleteDataset", "createEvaluation",
                                        "createFit",     "createJob",     "deleteJob",
                                        "pauseJob",      "resumeJob",     "uploadAerosols"};
  for (const char* id : kOperationIds) {
    const Json& operation = *operation_doc(id);
    if (writes.contains(id)) {
      EXPECT_EQ(operation["security"], Json::parse(R"([{"bearer": []}])")) << id;
      EXPECT_TRUE(operation["responses"].contains("401")) << id;
      EXPECT_TRUE(operation["responses"].contains("403")) << id;
    } else {
      EXPECT_EQ(operation["security"], Json::array()) << id;
      EXPECT_FALSE(operation["responses"].contains("401")) << id;
    }
  }
  EXPECT_EQ(openapi_components()["securitySchemes"]["bearer"]["scheme"], "bearer");
}

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

TEST(OperationDocs, ModelParametersCarryEveryModelsRange) {
  const Json parameters = openapi_components()["parameters"];
  std::set<std::string> model_ids;
  for (const auto& id : parameters["model"]["schema"]["enum"]) model_ids.insert(id);
  for (const ModelFactory& factory : registered_models()) {
    const ModelDescriptor& d = *factory.descriptor;
    EXPECT_TRUE(model_ids.contains(d.id)) << d.id;
    for (const ParameterSpec& spec : d.parameters) {
      const std::string key = "model_parameter." + spec.name;
      ASSERT_TRUE(parameters.contains(key)) << key;
      const Json& p = parameters[key];
      EXPECT_EQ(p["name"], spec.name);
      Json schema = p["schema"];
      if (schema.contains("oneOf")) schema = schema["oneOf"][0];  // albedo: a number or "grass"
      // "integer" only when every model that lists it takes integers.
      if (!spec.integer) {
        EXPECT_EQ(schema["type"], "number") << key;
      }
      EXPECT_LE(schema["minimum"].get<double>(), spec.min_value) << key;
      EXPECT_GE(schema["maximum"].get<double>(), spec.max_value) << key;
      const std::string range =
          d.id + " [" + number_text(spec.min_value) + ", " + number_text(spec.max_value) + "]";
      EXPECT_NE(p["description"].get<std::string>().find(range), std::string::npos)
          << key << " lacks " << range;
    }
  }
}

}  // namespace
}  // namespace clearsky::api
